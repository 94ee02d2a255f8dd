#include "delay_line.h"

#include <algorithm>

namespace vt::link {

DelayLine::DelayLine(Deliver deliver) : m_deliver(std::move(deliver))
{
    // Precise: a coarse timer may fire up to 5 % early, which would undercut simulated wire time.
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setSingleShot(true);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { onTimeout(); });
}

DelayLine::Clock::time_point DelayLine::push(QByteArray bytes, Clock::time_point due)
{
    if (!m_items.empty())
        due = std::max(due, m_items.back().due);
    m_items.push_back({std::move(bytes), due});
    if (m_items.size() == 1)
        arm();
    return due;
}

void DelayLine::clear()
{
    m_items.clear();
    m_timer.stop();
    ++m_generation;
}

void DelayLine::arm()
{
    if (m_items.empty())
        return;
    using namespace std::chrono;
    const auto wait = m_items.front().due - Clock::now();
    // Qt timers count whole milliseconds: wait the whole milliseconds, then re-arm with 0 ms until
    // the chunk is due (onTimeout() never delivers early), so a simulated wire keeps sub-ms time.
    const auto ms = wait.count() > 0 ? duration_cast<milliseconds>(wait) : milliseconds(0);
    m_timer.start(static_cast<int>(std::min<milliseconds::rep>(ms.count(), 24 * 3600 * 1000)));
}

void DelayLine::onTimeout()
{
    const std::uint64_t generation = m_generation;
    while (!m_items.empty() && m_items.front().due <= Clock::now()) {
        const QByteArray bytes = std::move(m_items.front().bytes);
        m_items.pop_front();
        m_deliver(bytes);
        // The receiver may have cleared the line (closed the link) while handling the chunk.
        if (generation != m_generation)
            return;
    }
    arm();
}

} // namespace vt::link
