// ModbusPduServer: the part of the simulated Modbus front ends shared by RTU and TCP — one request
// PDU for a unit id in, the module's response PDU out (ARCHITECTURE.md "Protocol decisions":
// register = parameter ID, FC 3 ≤ 8 registers per the HCS rule, FC 6, exception = the HCS EXCE).
//  * Unit id = module address (DMA E22, OPAT DIP switch); on a point-to-point link one configured
//    unit (default 1) reaches the node's first module (the OPAT master, whose SADR 0 would be the
//    Modbus broadcast address).
//  * Serial line: unit 0 is the broadcast (Modbus over Serial Line §2.2), FC 6 goes to every
//    module unanswered. TCP (gateway): unit 0 is SADR 0, the OPAT master.
//  * A unit no module answers: silence on a serial line; on TCP (a gateway) exception 5, the
//    node's "timeout slave, address wrong or not installed". Two modules at one unit: silence on
//    a serial line (the answers collide), the node's duplicate-address code on TCP.
// Owner: a front end; single-threaded.
#pragma once

#include "modbus/pdu.h"
#include "sim/hcs_node.h"

#include <cstdint>
#include <optional>
#include <span>

namespace vt::dev::sim {

struct ModbusUnitOptions
{
    // Set: a point-to-point link; only this unit is answered, by the node's first module.
    std::optional<std::uint8_t> pointToPointUnit;
    // The server stands for a gateway (Modbus TCP): missing / duplicate units get an exception.
    bool gateway = false;
};

struct TimedPdu
{
    modbus::ResponsePdu pdu;
    std::int64_t readyAtUs = 0;
};

class ModbusPduServer
{
public:
    // The node must outlive the server.
    ModbusPduServer(HcsNode &node, ModbusUnitOptions options = {});

    // nullopt: no answer (broadcast, or a unit nobody answers on a serial line).
    std::optional<TimedPdu> handle(std::uint8_t unit, std::span<const std::uint8_t> pdu);

    HcsNode &node() { return m_node; }
    const ModbusUnitOptions &options() const { return m_options; }

private:
    std::optional<TimedPdu> unitFault(std::uint8_t function, std::size_t found) const;

    HcsNode &m_node;
    ModbusUnitOptions m_options;
};

} // namespace vt::dev::sim
