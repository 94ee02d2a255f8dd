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
    // The Wandfluh ED1/SD1's PROFIBUS-DP cyclic image (PKW + PZD, ED1/SD1 manual §4.5, §4.6) as
    // a PC reaches it (ARCHITECTURE.md "Wandfluh ED1/SD1 online"):
    Dsp408Image,   // the raw output / input images exchanged cyclically over TCP
    Dsp408Gateway, // Modbus TCP registers of a PROFIBUS-master gateway (FC 16 out, FC 3/4 in)
};

inline constexpr std::array kLinkProtocols{LinkProtocol::ModbusRtu,    LinkProtocol::ModbusTcp,
                                           LinkProtocol::NodeImage,    LinkProtocol::Hart,
                                           LinkProtocol::Canopen,      LinkProtocol::Dsp408Image,
                                           LinkProtocol::Dsp408Gateway};

// "modbus-rtu", "modbus-tcp", "node-image", "hart", "canopen", "dsp408-image", "dsp408-gateway".
const char *key(LinkProtocol protocol);
// The ED1's PKW/PZD image over TCP (either mapping).
bool isDsp408Link(LinkProtocol protocol);
template<> std::optional<LinkProtocol> fromKey<LinkProtocol>(std::string_view key);

} // namespace vt::dev
