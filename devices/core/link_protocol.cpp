#include "core/link_protocol.h"

#include "core/key_lookup.h"

namespace vt::dev {

const char *key(LinkProtocol protocol)
{
    switch (protocol) {
    case LinkProtocol::ModbusRtu: return "modbus-rtu";
    case LinkProtocol::ModbusTcp: return "modbus-tcp";
    case LinkProtocol::NodeImage: return "node-image";
    case LinkProtocol::Hart: return "hart";
    case LinkProtocol::Canopen: return "canopen";
    case LinkProtocol::Dsp408Image: return "dsp408-image";
    case LinkProtocol::Dsp408Gateway: return "dsp408-gateway";
    }
    return "?";
}

bool isDsp408Link(LinkProtocol protocol)
{
    return protocol == LinkProtocol::Dsp408Image || protocol == LinkProtocol::Dsp408Gateway;
}

template<> std::optional<LinkProtocol> fromKey<LinkProtocol>(std::string_view text)
{
    return keyLookup<LinkProtocol>(kLinkProtocols, text);
}

} // namespace vt::dev
