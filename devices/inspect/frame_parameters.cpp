#include "frame_parameters.h"

#include "access/canopen_adapter.h"
#include "canopen/can_frame.h"
#include "canopen/sdo.h"
#include "dsp408/gateway.h"
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "hart/device_specific.h"
#include "hart/frame.h"
#include "hcs/telegram.h"
#include "modbus/register_image.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"

#include <type_traits>
#include <variant>

namespace vt::dev::inspect {
namespace {

void addRange(CarriedParameters &out, std::uint16_t first, std::uint32_t count)
{
    for (std::uint32_t i = 0; i < count && first + i <= 0xFFFFu; ++i)
        out.ids.push_back(static_cast<std::uint16_t>(first + i));
}

void fromModbusPdu(CarriedParameters &out, const modbus::RequestPdu &pdu)
{
    if (const auto *r = std::get_if<modbus::ReadRequest>(&pdu))
        addRange(out, r->start, r->count);
    else if (const auto *w = std::get_if<modbus::WriteRequest>(&pdu))
        out.ids.push_back(w->address);
}

void fromPkw(CarriedParameters &out, std::span<const std::uint8_t> pkwBytes,
             const ImageLayout &layout)
{
    dsp408::Options options = layout.dsp408;
    options.direction = Direction::Request;
    const auto pkw = dsp408::decodePkw(pkwBytes, options);
    if (pkw && pkw->ak != static_cast<std::uint8_t>(dsp408::RequestId::None))
        out.indPnu = CarriedParameters::IndPnu{pkw->ind, pkw->pnu, 0};
}

// A gateway write of the PKW words (4 registers) or the whole output image (7).
void fromGatewayAdu(CarriedParameters &out, std::span<const std::uint8_t> adu,
                    const ImageLayout &layout)
{
    const auto cut = modbus::cutAdu(adu);
    if (!cut.ok() || !*cut)
        return;
    const auto request = modbus::decodeRegisterRequest((*cut)->pdu);
    const auto *write = request ? std::get_if<modbus::RegisterWrite>(&*request) : nullptr;
    if (!write || (write->values.size() != dsp408::kPkwRegisters &&
                   write->values.size() != dsp408::kImageRegisters))
        return;
    const Bytes bytes = dsp408::fromRegisters(write->values, layout.registerBytes);
    fromPkw(out, std::span<const std::uint8_t>(bytes).first(dsp408::kPkwSize), layout);
}

void fromSdo(CarriedParameters &out, std::span<const std::uint8_t> data)
{
    const auto sdo = canopen::decodeSdo(data, Direction::Request);
    if (sdo && (sdo->command == canopen::SdoCommand::InitiateUploadRequest ||
                sdo->command == canopen::SdoCommand::InitiateDownloadRequest))
        out.canObject = CanObject{sdo->index, sdo->subindex};
}

} // namespace

CarriedParameters carriedBy(LinkProtocol link, std::span<const std::uint8_t> bytes,
                            Direction direction, hcs::Family family, const ImageLayout &layout)
{
    CarriedParameters out;
    if (direction != Direction::Request)
        return out;
    switch (link) {
    case LinkProtocol::NodeImage: {
        const auto request = hcs::decodeRequest(bytes, hcs::DecodeOptions{family, true});
        if (!request)
            break;
        if (const auto *r = std::get_if<hcs::ReadRequest>(&*request))
            addRange(out, r->firstId, r->count);
        else if (const auto *w = std::get_if<hcs::WriteRequest>(&*request))
            out.ids.push_back(w->id);
        break;
    }
    case LinkProtocol::ModbusRtu:
        if (const auto r = modbus::decodeRtuRequest(bytes))
            fromModbusPdu(out, r->pdu);
        break;
    case LinkProtocol::ModbusTcp:
        if (const auto r = modbus::decodeTcpRequest(bytes))
            fromModbusPdu(out, r->pdu);
        break;
    case LinkProtocol::Hart: {
        const auto frame = hart::decodeFrame(bytes);
        if (!frame || frame->isResponse() || !hart::isParameterCommand(frame->command))
            break;
        if (const auto access = hart::decodeParamAccess(frame->command, false, frame->data))
            out.indPnu =
                CarriedParameters::IndPnu{access->ref.ind, access->ref.pnu, access->ref.instance};
        break;
    }
    case LinkProtocol::Dsp408Image:
        if (bytes.size() == dsp408::kTelegram1Size)
            fromPkw(out, bytes.first(dsp408::kPkwSize), layout);
        break;
    case LinkProtocol::Dsp408Gateway: fromGatewayAdu(out, bytes, layout); break;
    case LinkProtocol::Canopen:
        if (bytes.size() == canopen::kSocketCanFrameSize) {
            const auto frame = canopen::fromSocketCan(bytes);
            if (frame && !frame->extended && !frame->rtr && !frame->errorFrame)
                fromSdo(out, frame->payload());
        } else {
            fromSdo(out, bytes);
        }
        break;
    }
    return out;
}

std::vector<const ParamMeta *> rowsOf(const CarriedParameters &carried,
                                      const Dictionary &dictionary)
{
    std::vector<const ParamMeta *> rows;
    for (std::uint16_t id : carried.ids)
        if (const ParamMeta *p = dictionary.findId(id))
            rows.push_back(p);
    if (carried.indPnu)
        if (const ParamMeta *p = dictionary.findIndPnu(carried.indPnu->ind, carried.indPnu->pnu,
                                                       carried.indPnu->instance))
            rows.push_back(p);
    if (carried.canObject) {
        const auto profile = access::canopenProfileOf(dictionary.protocol);
        for (const ParamMeta &p : dictionary.params) {
            const auto object = access::canopenObjectOf(p, profile);
            if (object && object->index == carried.canObject->index &&
                object->sub == carried.canObject->sub) {
                rows.push_back(&p);
                break;
            }
        }
    }
    return rows;
}

} // namespace vt::dev::inspect
