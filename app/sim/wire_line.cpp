#include "wire_line.h"

#include "modbus/rtu_timing.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <poll.h>
#include <string>
#include <sys/prctl.h>
#include <unistd.h>

namespace vt::simapp {

WireLine::WireLine(int fd, int baud, int bitsPerCharacter, std::int64_t turnaroundUs,
                   std::function<std::int64_t()> now, std::function<void(const std::string &)> note)
    : m_fd(fd), m_characterUs(dev::modbus::characterTimeUs(baud, bitsPerCharacter)),
      m_silenceUs(dev::modbus::silentIntervalUs(baud, bitsPerCharacter)),
      m_turnaroundUs(turnaroundUs), m_now(std::move(now)), m_note(std::move(note))
{
    // Each byte waits for its character time (95 µs at 115200 baud); Linux lets a timed wait end
    // up to 50 µs late by default, which would stretch the simulated wire.
    ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
}

bool WireLine::arrived(std::size_t bytes, std::int64_t nowUs)
{
    // Within t3.5 of the last received byte the same frame goes on (refused or not); after it a
    // new request starts, and the line must have been quiet for t3.5 since its last byte in
    // either direction (Modbus over Serial Line §2.5.1.1).
    const bool newFrame = nowUs >= m_rxEndUs + m_silenceUs;
    if (newFrame) {
        const std::int64_t lineLast = std::max(m_rxEndUs, m_txEndUs);
        m_refusing = nowUs - lineLast < m_silenceUs;
        if (m_refusing)
            refuse(nowUs);
    }
    m_rxEndUs = std::max(nowUs, m_rxEndUs) + static_cast<std::int64_t>(bytes) * m_characterUs;
    return !m_refusing;
}

void WireLine::refuse(std::int64_t nowUs)
{
    ++m_refusals;
    const std::int64_t quiet = nowUs - std::max(m_rxEndUs, m_txEndUs);
    char text[160];
    std::snprintf(text, sizeof text,
                  "wire: refused request (%llu so far): it started %.3f ms after the line's last "
                  "byte, t3.5 is %.3f ms",
                  static_cast<unsigned long long>(m_refusals), static_cast<double>(quiet) / 1000.0,
                  static_cast<double>(m_silenceUs) / 1000.0);
    m_note(text);
}

bool WireLine::waitUntil(std::int64_t untilUs)
{
    for (;;) {
        const std::int64_t now = m_now();
        if (now >= untilUs)
            return true;
        const std::int64_t left = untilUs - now;
        pollfd p{m_fd, POLLIN, 0};
        const timespec wait{static_cast<time_t>(left / 1'000'000),
                            static_cast<long>(left % 1'000'000) * 1000};
        const int ready = ::ppoll(&p, 1, &wait, nullptr);
        if (ready < 0 && errno != EINTR)
            return false;
        if (ready <= 0 || (p.revents & POLLIN) == 0)
            continue;
        // The master talks while the device's answer is due or on the line: a collision on a
        // half-duplex line; what it sent is lost to the device.
        std::uint8_t buf[512];
        const ssize_t n = ::read(m_fd, buf, sizeof buf);
        if (n > 0) {
            const std::int64_t at = m_now();
            if (at >= m_rxEndUs + m_silenceUs) { // a new frame, not the rest of the request
                ++m_collisions;
                m_note("wire: collision (" + std::to_string(m_collisions) +
                       " so far): the master sent while the device's answer was due or on the "
                       "line; ignored");
            }
            m_rxEndUs = std::max(at, m_rxEndUs) + static_cast<std::int64_t>(n) * m_characterUs;
            m_refusing = true;
        }
        if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR))
            return false;
    }
}

bool WireLine::transmit(std::span<const std::uint8_t> answer)
{
    const std::int64_t start = std::max({m_now(), m_rxEndUs + m_turnaroundUs, m_txEndUs});
    std::size_t sent = 0;
    while (sent < answer.size()) {
        // Every byte that has finished its character time by now goes out; a late wake-up
        // sends the ones due together instead of shifting the rest.
        if (!waitUntil(start + static_cast<std::int64_t>(sent + 1) * m_characterUs))
            return false;
        const std::int64_t now = m_now();
        std::size_t due = sent + 1;
        while (due < answer.size() &&
               start + static_cast<std::int64_t>(due + 1) * m_characterUs <= now)
            ++due;
        while (sent < due) {
            // The line's last byte counts from the moment it was handed to the pty: the master
            // cannot have seen it sooner. Taken after write() instead, a pause of this process
            // between the two would move the line's end later than the master saw it, and a
            // master that kept t3.5 would be refused.
            const std::int64_t handedOn = m_now();
            const ssize_t n = ::write(m_fd, answer.data() + sent, due - sent);
            if (n < 0 && errno != EAGAIN && errno != EINTR)
                return false;
            if (n < 0 && errno == EAGAIN) { // nobody reads: wait for room, briefly
                pollfd out{m_fd, POLLOUT, 0};
                ::poll(&out, 1, 10);
            }
            if (n > 0) {
                sent += static_cast<std::size_t>(n);
                m_txEndUs = handedOn;
            }
        }
    }
    return true;
}

} // namespace vt::simapp
