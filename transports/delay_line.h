// DelayLine: an in-order FIFO of byte chunks, each delivered by a callback no earlier than its due
// time, from the event loop (never from push()). SimLink uses it for wire time, FaultLink for
// injected delay. Owned by one link; lives on and is used from that link's thread only.
#pragma once

#include <QByteArray>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>

namespace vt::link {

class DelayLine
{
public:
    using Clock = std::chrono::steady_clock;
    using Deliver = std::function<void(const QByteArray &)>;

    explicit DelayLine(Deliver deliver);
    DelayLine(const DelayLine &) = delete;
    DelayLine &operator=(const DelayLine &) = delete;

    // Due times are clamped to be ≥ the previous chunk's, so delivery order is push order.
    // Returns the due time actually used.
    Clock::time_point push(QByteArray bytes, Clock::time_point due);
    // Drops everything pending (a chunk being delivered right now is not recalled).
    void clear();
    bool isEmpty() const { return m_items.empty(); }
    std::size_t size() const { return m_items.size(); }

private:
    struct Item
    {
        QByteArray bytes;
        Clock::time_point due;
    };

    void arm();
    void onTimeout();

    Deliver m_deliver;
    QTimer m_timer;
    std::deque<Item> m_items;
    std::uint64_t m_generation = 0;
};

} // namespace vt::link
