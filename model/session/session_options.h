// SessionOptions: how patient the session is with one link — wire speed for the timeout, the
// device's turnaround, retries and back-off. A plain value; any thread.
#pragma once

#include <chrono>
#include <cstddef>

namespace vt::model {

struct SessionOptions
{
    // Serial wire: the timeout covers request + reply at this speed. 0: no serial wire (TCP, CAN,
    // an in-process simulator without wire timing): the turnaround alone.
    int baudRate = 0;
    int bitsPerCharacter = 11; // 8E1 / 8O1 (HCS default 19200 8E1, HART 1200 8O1)
    // What the device may take between the end of the request and the start of its answer, plus
    // the scheduling slack of a desktop OS. HCS: DMA Profinet manual §3.4.1 names 25 ms for an
    // EEPROM write; 100 ms leaves room for a USB serial adapter's latency.
    std::chrono::milliseconds turnaround{100};
    // Modbus RTU line timing on a serial link (Modbus over Serial Line §2.5.1.1): the link may
    // hold a request for t3.5 and hands an answer on t3.5 after its last byte; both add to the
    // timeout. Zero without the RTU line timing.
    std::chrono::microseconds lineSilence{0};
    int retries = 3;                       // attempts after the first one
    std::chrono::milliseconds backoff{20}; // before the first retry; doubles each retry
    std::chrono::milliseconds maxBackoff{500};
    std::size_t maxQueued = 100'000; // refuse more instead of growing without bound
    // Cyclic links (the ED1's PROFIBUS image): how long to wait before asking again for an image
    // that did not show the answer yet — about one bus cycle of the PLC or gateway. Ours.
    std::chrono::milliseconds busCycle{5};

    // Time on the wire for `bytes` characters (zero without a serial wire).
    std::chrono::microseconds wireTime(std::size_t bytes) const
    {
        if (baudRate <= 0)
            return std::chrono::microseconds(0);
        const auto bits = static_cast<long long>(bytes) * bitsPerCharacter;
        return std::chrono::microseconds((bits * 1'000'000LL + baudRate - 1) / baudRate);
    }

    // How long to wait for the answer to a request of `requestBytes` whose answer is at most
    // `replyBytes` long.
    std::chrono::milliseconds timeout(std::size_t requestBytes, std::size_t replyBytes) const
    {
        const auto wire = wireTime(requestBytes + replyBytes) + 2 * lineSilence;
        return turnaround + std::chrono::ceil<std::chrono::milliseconds>(wire);
    }

    std::chrono::milliseconds backoffBefore(int retry) const
    {
        auto wait = backoff;
        for (int i = 1; i < retry && wait < maxBackoff; ++i)
            wait *= 2;
        return wait < maxBackoff ? wait : maxBackoff;
    }
};

} // namespace vt::model
