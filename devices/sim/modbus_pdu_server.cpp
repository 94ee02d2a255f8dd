#include "sim/modbus_pdu_server.h"

#include "modbus/exceptions.h"
#include "sim/hcs_codes.h"

namespace vt::dev::sim {
namespace {

TimedPdu exceptionPdu(std::uint8_t function, std::uint8_t code, std::int64_t at)
{
    return {modbus::ExceptionResponse{static_cast<std::uint8_t>(function & 0x7F), code}, at};
}

} // namespace

ModbusPduServer::ModbusPduServer(HcsNode &node, ModbusUnitOptions options)
    : m_node(node), m_options(options)
{
}

std::optional<TimedPdu> ModbusPduServer::unitFault(std::uint8_t function, std::size_t found) const
{
    if (!m_options.gateway)
        return std::nullopt; // nobody answers, or two answers collide on the wire
    const std::int64_t now = m_node.clock().nowUs();
    if (found == 0)
        return exceptionPdu(function, exce::kSlaveTimeout, now);
    return exceptionPdu(
        function, m_node.family() == hcs::Family::Opat ? exce::kDuplicateAddress : exce::kChecksum,
        now);
}

std::optional<TimedPdu> ModbusPduServer::handle(std::uint8_t unit,
                                                std::span<const std::uint8_t> pdu)
{
    if (pdu.empty())
        return std::nullopt;
    const std::uint8_t function = pdu[0];
    const std::int64_t now = m_node.clock().nowUs();
    // Modbus TCP has no broadcast: there unit 0 is SADR 0, the OPAT master.
    const bool broadcast = unit == 0 && !m_options.pointToPointUnit && !m_options.gateway;

    std::vector<HcsModule *> modules;
    if (m_options.pointToPointUnit) {
        if (unit != *m_options.pointToPointUnit || m_node.moduleCount() == 0 ||
            !m_node.module(0).powered())
            return std::nullopt;
        modules.push_back(&m_node.module(0));
    } else if (broadcast) {
        for (std::size_t i = 0; i < m_node.moduleCount(); ++i)
            if (m_node.module(i).powered())
                modules.push_back(&m_node.module(i));
    } else {
        modules = m_node.modulesAt(unit);
        if (modules.size() != 1)
            return unitFault(function, modules.size());
    }

    const auto request = modbus::decodeRequestPdu(pdu);
    if (!request) {
        if (broadcast)
            return std::nullopt;
        // Modbus Application Protocol §7: 1 illegal function, 3 illegal data value (a quantity
        // outside 1..125 — the HCS "CNT == 0 or CNT > 16" as well).
        const bool unknown = request.error().code == DecodeErrc::UnexpectedCommand;
        return exceptionPdu(function,
                            unknown ? modbus::kIllegalFunction : modbus::kIllegalDataValue, now);
    }

    if (const auto *read = std::get_if<modbus::ReadRequest>(&*request)) {
        if (broadcast)
            return std::nullopt; // a broadcast read has nobody to answer
        ReadOutcome out = modules.front()->read(read->start, read->count);
        if (!out.ok())
            return exceptionPdu(function, out.exception, now);
        return TimedPdu{modbus::ReadResponse{std::move(out.values)}, now};
    }
    const auto &write = std::get<modbus::WriteRequest>(*request);
    if (broadcast) {
        for (HcsModule *m : modules)
            (void)m->write(write.address, write.value);
        return std::nullopt;
    }
    const WriteOutcome out = modules.front()->write(write.address, write.value);
    if (!out.ok())
        return exceptionPdu(function, out.exception, out.readyAtUs);
    return TimedPdu{modbus::WriteResponse{write.address, write.value}, out.readyAtUs};
}

} // namespace vt::dev::sim
