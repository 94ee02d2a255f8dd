// WireLine: valvetune-sim --wire, the timing of a Modbus RTU line as a strict slave sees it on a
// pty or serial port (Modbus over Serial Line V1.02 §2.5.1.1). A pty moves bytes at once; the
// wire line gives each byte its character time at the configured baud and character format:
// a request's bytes end on the wire one character after the other from their arrival, the answer
// starts the device turnaround after the request's last byte, and its bytes are written one at
// a time, each when its stop bit would end. A request that starts before the line was quiet for
// t3.5 after its last byte in either direction is ignored, as a strict slave drops it, and
// counted; so is what the master sends while the answer is due or on the line (a collision,
// counted apart). Transmitting blocks the simulator's thread for the answer's wire time (≤ 256
// characters): the device talks, the line is busy, a half-duplex slave hears nothing meanwhile.
// Owner: SimHost; main thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace vt::simapp {

class WireLine
{
public:
    // `fd`: the non-blocking pty master or serial port; `now` a monotonic clock in µs; `note`
    // one line on stderr for each refusal.
    WireLine(int fd, int baud, int bitsPerCharacter, std::int64_t turnaroundUs,
             std::function<std::int64_t()> now, std::function<void(const std::string &)> note);

    // Bytes the master sent, read at `nowUs`: true when they are for the device, false when
    // they belong to a request that started too early (ignored).
    bool arrived(std::size_t bytes, std::int64_t nowUs);
    // Writes `answer` paced to the wire; false when the descriptor failed (errno set).
    bool transmit(std::span<const std::uint8_t> answer);

    // The last byte of the request being received ends on the wire at this time (for the
    // simulator's own end-of-frame gap).
    std::int64_t receiveEndsAtUs() const { return m_rxEndUs; }
    std::int64_t silenceUs() const { return m_silenceUs; }
    // Requests that started too soon after the line's last byte (the master's fault).
    std::uint64_t refusals() const { return m_refusals; }
    // Frames the master sent while the device's answer was due or on the line: a retry after the
    // master's timeout meeting a late answer, as on a real half-duplex line.
    std::uint64_t collisions() const { return m_collisions; }

private:
    // Waits until `untilUs`; bytes the master sends meanwhile collide with ours: read, dropped.
    bool waitUntil(std::int64_t untilUs);
    void refuse(std::int64_t nowUs);

    int m_fd;
    std::int64_t m_characterUs;
    std::int64_t m_silenceUs;
    std::int64_t m_turnaroundUs;
    std::function<std::int64_t()> m_now;
    std::function<void(const std::string &)> m_note;
    std::int64_t m_rxEndUs = -1'000'000'000; // the last received byte's stop bit
    std::int64_t m_txEndUs = -1'000'000'000; // the last transmitted byte's, handed on
    bool m_refusing = false;                 // the request on the line is being ignored
    std::uint64_t m_refusals = 0;
    std::uint64_t m_collisions = 0;
};

} // namespace vt::simapp
