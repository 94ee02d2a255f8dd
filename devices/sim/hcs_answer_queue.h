// AnswerQueue: what a simulator front end has answered but not yet sent, each answer with the
// simulated time it is ready (a write delayed by a busy EEPROM, DMA Profinet manual §3.4.1).
// Answers leave in order, like on a wire: a later one never overtakes an earlier one.
// Owner: one front end (ByteServer); single-threaded.
#pragma once

#include "core/byte_writer.h"

#include <cstdint>
#include <deque>
#include <optional>

namespace vt::dev::sim {

struct TimedBytes
{
    Bytes bytes;
    std::int64_t readyAtUs = 0; // simulated time (SimClock::nowUs) from which it may be sent
};

class AnswerQueue
{
public:
    void push(TimedBytes answer) { m_queue.push_back(std::move(answer)); }

    // Everything ready at `nowUs`, in order, stopping at the first answer not ready yet.
    Bytes take(std::int64_t nowUs)
    {
        Bytes out;
        while (!m_queue.empty() && m_queue.front().readyAtUs <= nowUs) {
            const Bytes &b = m_queue.front().bytes;
            out.insert(out.end(), b.begin(), b.end());
            m_queue.pop_front();
        }
        return out;
    }

    // When the next answer becomes ready; nullopt when nothing is queued. A pump that drives the
    // clock advances it to this time instead of sleeping.
    std::optional<std::int64_t> nextReadyUs() const
    {
        if (m_queue.empty())
            return std::nullopt;
        return m_queue.front().readyAtUs;
    }

    std::size_t size() const { return m_queue.size(); }
    void clear() { m_queue.clear(); }

private:
    std::deque<TimedBytes> m_queue;
};

} // namespace vt::dev::sim
