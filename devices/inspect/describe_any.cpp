#include "describe_any.h"

#include "canopen/sdo.h"
#include "dict/cooking.h"
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "hart/describe.h"
#include "hcs/describe.h"
#include "hcs/profiles.h"
#include "logged_frame.h"
#include "modbus/describe.h"
#include "profidrive/describe.h"

namespace vt::dev {

const std::vector<Protocol> &allProtocols()
{
    static const std::vector<Protocol> all = {
        Protocol::Gateway, Protocol::ModbusRtu, Protocol::ModbusTcp, Protocol::Profidrive,
        Protocol::Pkw,     Protocol::Pzd,       Protocol::Hart,      Protocol::Canopen};
    return all;
}

const char *protocolName(Protocol protocol)
{
    switch (protocol) {
    case Protocol::Gateway: return "gateway";
    case Protocol::ModbusRtu: return "modbus-rtu";
    case Protocol::ModbusTcp: return "modbus-tcp";
    case Protocol::Profidrive: return "profidrive";
    case Protocol::Pkw: return "pkw";
    case Protocol::Pzd: return "pzd";
    case Protocol::Hart: return "hart";
    case Protocol::Canopen: return "canopen";
    }
    return "?";
}

std::optional<Protocol> protocolFromName(std::string_view name)
{
    for (Protocol p : allProtocols())
        if (name == protocolName(p))
            return p;
    return std::nullopt;
}

namespace {

// HCS parameter names and cooked values: one definition, shared with the telegram log.
hcs::ParameterHooks hooksFor(const Dictionary *dict)
{
    return inspect::parameterHooks(dict);
}

} // namespace

Result<Description, std::string> describeAny(std::span<const std::uint8_t> bytes,
                                             const AnyOptions &options)
{
    std::optional<hcs::Profile> profile;
    if (!options.profile.empty()) {
        profile = hcs::profileByKey(options.profile);
        if (!profile)
            return std::string("unknown CMD 15 profile '" + options.profile + "'");
    }
    hcs::DescribeOptions node;
    node.family = options.family;
    node.direction = options.direction;
    node.profile = profile;
    node.parameters = hooksFor(options.dictionary);

    switch (options.protocol) {
    case Protocol::Gateway: return hcs::describe(bytes, node);
    case Protocol::ModbusRtu:
    case Protocol::ModbusTcp: {
        modbus::DescribeOptions o;
        o.direction = options.direction;
        o.family = options.family;
        o.parameters = node.parameters;
        return options.protocol == Protocol::ModbusRtu ? modbus::describeRtu(bytes, o)
                                                       : modbus::describeTcp(bytes, o);
    }
    case Protocol::Profidrive: {
        profidrive::DescribeOptions o;
        o.direction = options.direction;
        o.node = node;
        o.node.family = hcs::Family::Opat; // OPAT manual §5: only the OPAT node speaks PROFIdrive
        return profidrive::describe(bytes, o);
    }
    case Protocol::Pkw:
    case Protocol::Pzd: {
        dsp408::Options o;
        o.direction = options.direction;
        return options.protocol == Protocol::Pkw ? dsp408::describePkw(bytes, o)
                                                 : dsp408::describeTelegram(bytes, o);
    }
    case Protocol::Hart: return hart::describeFrame(bytes);
    case Protocol::Canopen: {
        canopen::DescribeOptions o;
        o.cobId = options.cobId;
        o.direction = options.direction;
        return canopen::describeSdo(bytes, o);
    }
    }
    return std::string("unknown protocol");
}

} // namespace vt::dev
