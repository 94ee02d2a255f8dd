#include "sim/canopen_sdo_server.h"

#include "canopen/can_frame.h"
#include "core/byte_reader.h"

#include <utility>

namespace vt::dev::sim {

using canopen::Sdo;
using canopen::SdoCommand;

CanopenSdoServer::CanopenSdoServer(ObjectDictionary &objects, std::uint8_t node)
    : m_objects(objects), m_node(node)
{
}

void CanopenSdoServer::receive(std::span<const std::uint8_t> bytes)
{
    m_in.insert(m_in.end(), bytes.begin(), bytes.end());
    std::size_t used = 0;
    while (m_in.size() - used >= canopen::kSocketCanFrameSize) {
        frame(std::span<const std::uint8_t>(m_in).subspan(used, canopen::kSocketCanFrameSize));
        used += canopen::kSocketCanFrameSize;
    }
    m_in.erase(m_in.begin(), m_in.begin() + static_cast<std::ptrdiff_t>(used));
}

std::vector<std::uint8_t> CanopenSdoServer::drain()
{
    return std::exchange(m_out, {});
}

void CanopenSdoServer::frame(std::span<const std::uint8_t> image)
{
    auto can = canopen::fromSocketCan(image);
    if (!can.ok() || can->extended || can->rtr || can->errorFrame ||
        can->id != canopen::sdoRequestId(m_node)) {
        ++m_ignored;
        return;
    }
    auto sdo = canopen::decodeSdo(can->payload(), Direction::Request);
    if (!sdo.ok()) {
        // CiA 301: an SDO is always 8 bytes; answer what we can tell (index and sub-index are
        // bytes 1..3, little-endian) with "command specifier not valid".
        ByteReader r(can->payload());
        r.skip(1);
        const std::uint16_t index = r.u16le();
        const std::uint8_t sub = r.u8();
        send(canopen::abortTransfer(index, sub, sdo_abort::kCommandSpecifier));
        return;
    }
    if (sdo->command == SdoCommand::Abort)
        return; // the client gives up a transfer; we never keep one open
    send(serve(*sdo));
}

Sdo CanopenSdoServer::serve(const Sdo &request)
{
    ++m_served;
    switch (request.command) {
    case SdoCommand::InitiateUploadRequest: {
        auto value = m_objects.read(request.index, request.subindex);
        if (!value.ok())
            return canopen::abortTransfer(request.index, request.subindex, value.error().code);
        return canopen::expeditedUploadResponse(request.index, request.subindex, value->bits,
                                                value->size);
    }
    case SdoCommand::InitiateDownloadRequest: {
        if (!request.expedited) {
            // Segmented download: every object here fits an expedited transfer (≤ 4 bytes).
            const bool tooLong = request.sizeIndicated && request.size > 4;
            return canopen::abortTransfer(request.index, request.subindex,
                                          tooLong ? sdo_abort::kLengthTooHigh
                                                  : sdo_abort::kCommandSpecifier);
        }
        const std::size_t size = request.sizeIndicated ? request.data.size() : 0;
        if (auto abort = m_objects.write(request.index, request.subindex,
                                         canopen::expeditedValue(request), size))
            return canopen::abortTransfer(request.index, request.subindex, abort->code);
        return canopen::downloadResponse(request.index, request.subindex);
    }
    default:
        // Segments without an open transfer, block transfers: not served (expedited only).
        return canopen::abortTransfer(request.index, request.subindex,
                                      sdo_abort::kCommandSpecifier);
    }
}

void CanopenSdoServer::send(const Sdo &response)
{
    auto can = canopen::toCanFrame(response, m_node, Direction::Response);
    if (!can.ok())
        return;
    const auto image = canopen::toSocketCan(*can);
    m_out.insert(m_out.end(), image.begin(), image.end());
}

} // namespace vt::dev::sim
