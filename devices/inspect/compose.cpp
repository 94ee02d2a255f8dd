#include "compose.h"

#include "canopen/can_frame.h"
#include "canopen/sdo.h"
#include "dsp408/pkw.h"
#include "hart/device_specific.h"
#include "hart/frame.h"
#include "hcs/node_rules.h"
#include "hcs/telegram.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"

#include <algorithm>

namespace vt::dev::inspect {
namespace {

struct Check
{
    std::string problem;
    ComposeError first{std::string()};
    // `name` as the manuals write it (the reason), `field` the ComposeSpec member.
    bool in(const char *name, const char *field, long long v, long long min, long long max)
    {
        if ((v < min || v > max) && problem.empty()) {
            problem =
                std::string(name) + " must be " + std::to_string(min) + ".." + std::to_string(max);
            first = ComposeError{problem, field, min, max};
        }
        return problem.empty();
    }
    ComposeError error() const { return first; }
};

std::uint8_t u8(long long v)
{
    return static_cast<std::uint8_t>(v);
}
std::uint16_t u16(long long v)
{
    return static_cast<std::uint16_t>(v);
}

// HART-7 manual §2.3 / §4.2: commands that only read (universal and Wandfluh's 128/130/132);
// every other command may change the device and is confirmed before it is sent.
bool hartReadsOnly(long long command)
{
    static constexpr int kReads[] = {0,  1,  2,  3,  7,  8,  9,   11,  12, 13,
                                     14, 15, 16, 20, 21, 48, 128, 130, 132};
    return std::find(std::begin(kReads), std::end(kReads), command) != std::end(kReads);
}

long long valueMin(int width)
{
    return width == 4 ? -2147483648LL : width == 2 ? -32768 : -128;
}
long long valueMax(int width)
{
    return width == 4 ? 4294967295LL : width == 2 ? 65535 : 255;
}

} // namespace

Result<ComposedFrame, ComposeError> compose(const ComposeSpec &s)
{
    Check c;
    ComposedFrame out;
    switch (s.kind) {
    case ComposeKind::GatewayRead:
    case ComposeKind::GatewayWrite: {
        out.protocol = FrameFormat::Gateway;
        out.link = LinkProtocol::NodeImage;
        c.in("TADR", "tadr", s.tadr, 0, 255);
        c.in("SADR", "sadr", s.sadr, 0, 255);
        c.in("ID", "id", s.id, 0, 0xFFFF);
        if (s.kind == ComposeKind::GatewayRead) {
            c.in("N", "count", s.count, 1, hcs::kMaxReadCount); // OPAT manual §2.1: at most 8
            if (!c.problem.empty())
                return c.error();
            out.bytes =
                hcs::encode(hcs::ReadRequest{u8(s.tadr), u8(s.sadr), u16(s.id), u16(s.count)});
        } else {
            c.in("value", "value", s.value, -32768, 65535);
            if (!c.problem.empty())
                return c.error();
            out.bytes =
                hcs::encode(hcs::WriteRequest{u8(s.tadr), u8(s.sadr), u16(s.id), u16(s.value)});
            out.writes = true;
        }
        return out;
    }
    case ComposeKind::GatewayCyclic: {
        out.protocol = FrameFormat::Gateway;
        out.link = LinkProtocol::NodeImage;
        out.writes = true; // set values move the valve
        if (!c.in("TADR", "tadr", s.tadr, 0, 255))
            return c.error();
        const auto bytes = hcs::encode(hcs::CyclicRequest{u8(s.tadr), s.modules}, s.family);
        if (!bytes)
            return ComposeError{"a " + std::string(hcs::familyName(s.family)) +
                                " node cannot carry " + std::to_string(s.modules.size()) +
                                " modules in CMD 15"};
        out.bytes = *bytes;
        return out;
    }
    case ComposeKind::ModbusRead:
    case ComposeKind::ModbusWrite: {
        out.protocol = s.modbusTcp ? FrameFormat::ModbusTcp : FrameFormat::ModbusRtu;
        out.link = s.modbusTcp ? LinkProtocol::ModbusTcp : LinkProtocol::ModbusRtu;
        c.in("unit", "unit", s.unit, 0, 255);
        c.in("register", "id", s.id, 0, 0xFFFF);
        c.in("transaction", "transaction", s.transaction, 0, 0xFFFF);
        modbus::RequestPdu pdu;
        if (s.kind == ComposeKind::ModbusRead) {
            c.in("count", "count", s.count, 1, modbus::kMaxReadRegisters);
            pdu = modbus::ReadRequest{u16(s.id), u16(s.count)};
        } else {
            c.in("value", "value", s.value, -32768, 65535);
            pdu = modbus::WriteRequest{u16(s.id), u16(s.value)};
            out.writes = true;
        }
        if (!c.problem.empty())
            return c.error();
        const auto bytes =
            s.modbusTcp ? modbus::encodeTcp(modbus::TcpRequest{u16(s.transaction), u8(s.unit), pdu})
                        : modbus::encodeRtu(modbus::RtuRequest{u8(s.unit), pdu});
        if (!bytes)
            return ComposeError{bytes.error().detail};
        out.bytes = *bytes;
        return out;
    }
    case ComposeKind::PkwRead:
    case ComposeKind::PkwWrite: {
        out.protocol = FrameFormat::Pkw;
        c.in("IND", "ind", s.ind, 0, 255);
        c.in("PNU", "pnu", s.pnu, 0, dsp408::kMaxPnu);
        dsp408::Pkw pkw = dsp408::readRequest(u8(s.ind), u16(s.pnu));
        if (s.kind == ComposeKind::PkwWrite) {
            if (s.width != 1 && s.width != 2 && s.width != 4)
                return ComposeError{std::string("width must be 1, 2 or 4 bytes")};
            c.in("value", "value", s.value, valueMin(s.width), valueMax(s.width));
            pkw = dsp408::writeRequest(u8(s.ind), u16(s.pnu),
                                       static_cast<dsp408::ParamLength>(s.width),
                                       static_cast<std::uint32_t>(s.value));
            out.writes = true;
        }
        if (!c.problem.empty())
            return c.error();
        const auto bytes = dsp408::encodePkw(pkw);
        if (!bytes)
            return ComposeError{bytes.error().detail};
        out.bytes = *bytes;
        return out;
    }
    case ComposeKind::HartCommand:
    case ComposeKind::HartParamRead:
    case ComposeKind::HartParamWrite: {
        out.protocol = FrameFormat::Hart;
        out.link = LinkProtocol::Hart;
        hart::Address address;
        if (s.hartDeviceType) {
            // longAddress() drops the two top bits of the expanded device type (HART-7 manual
            // §2.3).
            c.in("device id", "hartDeviceId", s.hartDeviceId, 0, hart::kMaxDeviceId);
            address = hart::longAddress(*s.hartDeviceType, s.hartDeviceId);
        } else {
            c.in("poll address", "pollAddress", s.pollAddress, 0, hart::kMaxPollAddress);
            address = hart::shortAddress(u8(s.pollAddress));
        }
        std::uint8_t command = 0;
        Bytes data;
        if (s.kind == ComposeKind::HartCommand) {
            c.in("command", "hartCommand", s.hartCommand, 0, 255);
            c.in("data bytes", "hartData", static_cast<long long>(s.hartData.size()), 0,
                 static_cast<long long>(hart::kMaxByteCount));
            command = u8(s.hartCommand);
            data = s.hartData;
            out.writes = !hartReadsOnly(s.hartCommand);
        } else {
            if (s.width != 1 && s.width != 2 && s.width != 4)
                return ComposeError{std::string("width must be 1, 2 or 4 bytes")};
            c.in("IND", "ind", s.ind, 0, 255);
            c.in("PNU", "pnu", s.pnu, 0, 255);
            c.in("instance", "instance", s.instance, 0, 255);
            const hart::ValueType type = s.width == 1   ? hart::ValueType::UInt8
                                         : s.width == 2 ? hart::ValueType::UInt16
                                                        : hart::ValueType::UInt32;
            const hart::ParamRef ref{u8(s.ind), u8(s.pnu), u8(s.instance)};
            hart::ParamAccess access = hart::readParam(type, ref);
            if (s.kind == ComposeKind::HartParamWrite) {
                c.in("value", "value", s.value, valueMin(s.width), valueMax(s.width));
                std::uint32_t raw = static_cast<std::uint32_t>(s.value);
                if (s.width < 4)
                    raw &= (1u << (8 * s.width)) - 1u;
                access = hart::writeParam(type, ref, raw);
                out.writes = true;
            }
            if (!c.problem.empty())
                return c.error();
            const auto payload = hart::encodeParamAccess(access, false);
            if (!payload)
                return ComposeError{payload.error().detail};
            command = access.command;
            data = *payload;
        }
        if (!c.problem.empty())
            return c.error();
        const auto bytes = hart::encodeFrame(hart::makeRequest(address, command, std::move(data)));
        if (!bytes)
            return ComposeError{bytes.error().detail};
        out.bytes = *bytes;
        return out;
    }
    case ComposeKind::SdoUpload:
    case ComposeKind::SdoDownload: {
        out.protocol = FrameFormat::Canopen;
        out.link = LinkProtocol::Canopen;
        c.in("node", "node", s.node, 1, 127); // CiA 301 §7.3.3: node ids 1..127
        c.in("index", "index", s.index, 0, 0xFFFF);
        c.in("sub-index", "subindex", s.subindex, 0, 255);
        canopen::Sdo sdo = canopen::uploadRequest(u16(s.index), u8(s.subindex));
        if (s.kind == ComposeKind::SdoDownload) {
            if (s.width != 1 && s.width != 2 && s.width != 4)
                return ComposeError{std::string("width must be 1, 2 or 4 bytes")};
            c.in("value", "value", s.value, valueMin(s.width), valueMax(s.width));
            std::uint32_t raw = static_cast<std::uint32_t>(s.value);
            if (s.width < 4)
                raw &= (1u << (8 * s.width)) - 1u;
            sdo = canopen::expeditedDownload(u16(s.index), u8(s.subindex), raw,
                                             static_cast<std::size_t>(s.width));
            out.writes = true;
        }
        if (!c.problem.empty())
            return c.error();
        const auto bytes = canopen::encodeSdo(sdo);
        if (!bytes)
            return ComposeError{bytes.error().detail};
        out.bytes = *bytes;
        out.cobId = canopen::sdoRequestId(u8(s.node));
        return out;
    }
    }
    return ComposeError{std::string("unknown frame kind")};
}

Bytes wireBytes(const ComposedFrame &frame, std::size_t imageBytes)
{
    if (frame.protocol == FrameFormat::Canopen && frame.cobId) {
        const auto image = canopen::toSocketCan(canopen::makeCanFrame(*frame.cobId, frame.bytes));
        return Bytes(image.begin(), image.end());
    }
    Bytes out = frame.bytes;
    if (frame.link == LinkProtocol::NodeImage && out.size() < imageBytes)
        out.resize(imageBytes, 0); // the rest of the output image (DMA Profinet manual §4.5.4)
    return out;
}

} // namespace vt::dev::inspect
