// LinkProtocol: the protocol a link speaks to a module or node — what the session's adapter
// frames, what the simulator serves and what the telegram log records for each frame. One
// vocabulary for the GUI, the CLI, the simulator and the tests; its keys are for the edges only.
#pragma once

#include "core/enum_key.h"

#include <array>
#include <optional>
#include <string_view>

namespace vt::dev {

enum class LinkProtocol {
    ModbusRtu, // serial line (RS232 point-to-point or RS485 multi-drop)
    ModbusTcp, // MBAP header, to a gateway or the simulator
    NodeImage, // the manuals' fixed-length node telegrams exchanged cyclically (over TCP)
    Hart,      // HART-7 through a modem on a serial line
    Canopen,   // CANopen SDO expedited transfers (SocketCAN)
};

inline constexpr std::array kLinkProtocols{LinkProtocol::ModbusRtu, LinkProtocol::ModbusTcp,
                                           LinkProtocol::NodeImage, LinkProtocol::Hart,
                                           LinkProtocol::Canopen};

// "modbus-rtu", "modbus-tcp", "node-image", "hart", "canopen".
const char *key(LinkProtocol protocol);
template<> std::optional<LinkProtocol> fromKey<LinkProtocol>(std::string_view key);

} // namespace vt::dev
