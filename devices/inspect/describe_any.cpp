#include "describe_any.h"

#include "canopen/sdo.h"
#include "core/key_lookup.h"
#include "dict/cooking.h"
#include "dsp408/gateway.h"
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "hart/describe.h"
#include "hcs/describe.h"
#include "hcs/profiles.h"
#include "logged_frame.h"
#include "modbus/describe.h"
#include "profidrive/describe.h"

namespace vt::dev {

const char *key(FrameFormat format)
{
    switch (format) {
    case FrameFormat::Gateway: return "gateway";
    case FrameFormat::ModbusRtu: return "modbus-rtu";
    case FrameFormat::ModbusTcp: return "modbus-tcp";
    case FrameFormat::Profidrive: return "profidrive";
    case FrameFormat::Pkw: return "pkw";
    case FrameFormat::Pzd: return "pzd";
    case FrameFormat::Hart: return "hart";
    case FrameFormat::Canopen: return "canopen";
    case FrameFormat::Dsp408Gateway: return "dsp408-gateway";
    }
    return "?";
}

template<> std::optional<FrameFormat> fromKey<FrameFormat>(std::string_view text)
{
    return keyLookup<FrameFormat>(kFrameFormats, text);
}

FrameFormat frameFormatOf(LinkProtocol protocol)
{
    switch (protocol) {
    case LinkProtocol::ModbusRtu: return FrameFormat::ModbusRtu;
    case LinkProtocol::ModbusTcp: return FrameFormat::ModbusTcp;
    case LinkProtocol::NodeImage: return FrameFormat::Gateway;
    case LinkProtocol::Hart: return FrameFormat::Hart;
    case LinkProtocol::Canopen: return FrameFormat::Canopen;
    case LinkProtocol::Dsp408Image: return FrameFormat::Pzd; // telegram type 1: PKW + PZD
    case LinkProtocol::Dsp408Gateway: return FrameFormat::Dsp408Gateway;
    }
    return FrameFormat::Gateway;
}

Result<Description, std::string> describeAny(std::span<const std::uint8_t> bytes,
                                             const AnyOptions &options)
{
    auto gateway = inspect::gatewayOptions(options);
    if (!gateway.ok())
        return gateway.error();
    const hcs::DescribeOptions &node = *gateway;

    switch (options.protocol) {
    case FrameFormat::Gateway: return hcs::describe(bytes, node);
    case FrameFormat::ModbusRtu:
    case FrameFormat::ModbusTcp: {
        modbus::DescribeOptions o;
        o.direction = options.direction;
        o.family = options.family;
        o.parameters = node.parameters;
        return options.protocol == FrameFormat::ModbusRtu ? modbus::describeRtu(bytes, o)
                                                          : modbus::describeTcp(bytes, o);
    }
    case FrameFormat::Profidrive: {
        profidrive::DescribeOptions o;
        o.direction = options.direction;
        o.node = node;
        o.node.family = hcs::Family::Opat; // OPAT manual §5: only the OPAT node speaks PROFIdrive
        return profidrive::describe(bytes, o);
    }
    case FrameFormat::Pkw:
    case FrameFormat::Pzd: {
        dsp408::Options o = options.dsp408;
        o.direction = options.direction;
        return options.protocol == FrameFormat::Pkw ? dsp408::describePkw(bytes, o)
                                                    : dsp408::describeTelegram(bytes, o);
    }
    case FrameFormat::Hart: return hart::describeFrame(bytes);
    case FrameFormat::Canopen: {
        canopen::DescribeOptions o;
        o.cobId = options.cobId;
        o.direction = options.direction;
        return canopen::describeSdo(bytes, o);
    }
    case FrameFormat::Dsp408Gateway: {
        dsp408::Options o = options.dsp408;
        o.direction = options.direction;
        return dsp408::describeGatewayAdu(bytes, o, options.registerBytes);
    }
    }
    return std::string("unknown protocol");
}

} // namespace vt::dev
