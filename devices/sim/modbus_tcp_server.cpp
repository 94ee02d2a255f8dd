#include "sim/modbus_tcp_server.h"

#include "modbus/tcp.h"

namespace vt::dev::sim {
namespace {

ModbusUnitOptions asGateway(ModbusUnitOptions options)
{
    options.gateway = true;
    return options;
}

} // namespace

ModbusTcpServer::ModbusTcpServer(SimClock &clock, HcsNode &node, ModbusUnitOptions options)
    : m_clock(clock), m_pdu(node, asGateway(options))
{
}

void ModbusTcpServer::receive(std::span<const std::uint8_t> bytes)
{
    for (const Bytes &frame : m_deframer.feed(bytes)) {
        const auto header = modbus::decodeMbap(frame);
        if (!header)
            continue; // the de-framer only delivers frames whose header it accepted
        const auto pdu = std::span<const std::uint8_t>(frame).subspan(modbus::kMbapSize);
        auto answer = m_pdu.handle(header->unit, pdu);
        if (!answer)
            continue;
        auto adu = modbus::encodeTcp(
            modbus::TcpResponse{header->transaction, header->unit, std::move(answer->pdu)});
        if (adu)
            m_answers.push({std::move(adu).value(), answer->readyAtUs});
    }
}

std::vector<std::uint8_t> ModbusTcpServer::drain()
{
    return m_answers.take(m_clock.nowUs());
}

void ModbusTcpServer::reset()
{
    m_deframer.reset();
    m_answers.clear();
}

} // namespace vt::dev::sim
