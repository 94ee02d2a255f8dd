// ModbusTcpServer: a simulated HCS node behind a Modbus TCP gateway (MBAP header, Modbus
// Messaging on TCP/IP Implementation Guide V1.0b §3.1.3), as a vt::dev::ByteServer. The unit id
// selects the module; the server answers for missing units as a gateway does (ModbusPduServer).
// A header that cannot be right puts the stream out of step: the server answers nothing more
// until reset() (the connection is re-established).
// Owner: the simulator front end / SimLink; single-threaded.
#pragma once

#include "core/byte_server.h"
#include "modbus/deframer.h"
#include "sim/hcs_answer_queue.h"
#include "sim/modbus_pdu_server.h"

namespace vt::dev::sim {

class ModbusTcpServer : public ByteServer
{
public:
    // The clock and the node must outlive the server. options.gateway is forced on.
    ModbusTcpServer(SimClock &clock, HcsNode &node, ModbusUnitOptions options = {});

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;

    // A new connection: forget buffered bytes, queued answers and a latched framing error.
    void reset();
    bool outOfStep() const { return m_deframer.error().has_value(); }
    std::optional<std::int64_t> nextAnswerUs() const { return m_answers.nextReadyUs(); }

private:
    SimClock &m_clock;
    ModbusPduServer m_pdu;
    modbus::TcpDeframer m_deframer;
    AnswerQueue m_answers;
};

} // namespace vt::dev::sim
