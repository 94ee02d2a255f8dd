#include "sim/modbus_rtu_server.h"

#include "modbus/rtu.h"

namespace vt::dev::sim {

ModbusRtuServer::ModbusRtuServer(SimClock &clock, HcsNode &node, ModbusUnitOptions options)
    : m_clock(clock), m_pdu(node, options)
{
}

void ModbusRtuServer::receive(std::span<const std::uint8_t> bytes)
{
    for (const Bytes &frame : m_deframer.feed(bytes)) {
        ++m_frames;
        // The de-framer hands out CRC-valid frames only: unit id, PDU, CRC (2 bytes).
        const std::uint8_t unit = frame.front();
        const auto pdu =
            std::span<const std::uint8_t>(frame).subspan(1, frame.size() - modbus::kRtuOverhead);
        auto answer = m_pdu.handle(unit, pdu);
        if (!answer)
            continue;
        auto adu = modbus::encodeRtu(modbus::RtuResponse{unit, std::move(answer->pdu)});
        if (adu)
            m_answers.push({std::move(adu).value(), answer->readyAtUs});
    }
}

std::vector<std::uint8_t> ModbusRtuServer::drain()
{
    return m_answers.take(m_clock.nowUs());
}

} // namespace vt::dev::sim
