// ModbusRtuServer: a simulated HCS node's modules on a Modbus RTU line (RS232 point-to-point or
// RS485 multi-drop; ARCHITECTURE.md "Protocol decisions"), as a vt::dev::ByteServer: bytes in as
// the line delivers them (frames split or run together; the RTU de-framer finds them by header
// and CRC), answers out through drain() once the simulated clock has reached them.
// Owner: the simulator front end / SimLink; single-threaded.
#pragma once

#include "core/byte_server.h"
#include "modbus/deframer.h"
#include "sim/hcs_answer_queue.h"
#include "sim/modbus_pdu_server.h"

namespace vt::dev::sim {

class ModbusRtuServer : public ByteServer
{
public:
    // The clock and the node must outlive the server.
    ModbusRtuServer(SimClock &clock, HcsNode &node, ModbusUnitOptions options = {});

    void receive(std::span<const std::uint8_t> bytes) override;
    // Answers whose time has come (SimClock::nowUs), in order.
    std::vector<std::uint8_t> drain() override;

    // The line was silent for 3.5 characters (Modbus over Serial Line §2.5.1.1): bytes of an
    // unfinished frame are dropped. The link calls this; a pty pump may call it between writes.
    void silence() { m_deframer.silence(); }

    // When the next queued answer is ready; nullopt when nothing is queued.
    std::optional<std::int64_t> nextAnswerUs() const { return m_answers.nextReadyUs(); }
    std::size_t framesHandled() const { return m_frames; }
    std::size_t garbageBytes() const { return m_deframer.discarded(); }
    ModbusPduServer &pduServer() { return m_pdu; }

private:
    SimClock &m_clock;
    ModbusPduServer m_pdu;
    modbus::RtuDeframer m_deframer{Direction::Request};
    AnswerQueue m_answers;
    std::size_t m_frames = 0;
};

} // namespace vt::dev::sim
