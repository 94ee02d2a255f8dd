// Bounded waits for every Qt test: they run a real event loop until a condition holds or the
// bound (kWaitMs, wait_bound.h) passes, so no test sleeps a fixed time; a check that something
// does NOT happen spins its own short window (spinFor).
#pragma once

#include "transports/link.h"
#include "wait_bound.h"

#include <QEventLoop>
#include <QSignalSpy>
#include <QTimer>
#include <optional>

namespace vt::test {

// Runs the event loop until `done()` holds (checked every millisecond) or `timeoutMs` passes.
// Unlike QTest::qWaitFor, which sleeps 10 ms between event batches, it never holds back the
// simulator's 1 ms clock or a poll timer, so it neither slows a test nor falsifies a rate.
template<typename Predicate> bool waitUntil(Predicate done, int timeoutMs = kWaitMs)
{
    if (done())
        return true;
    QEventLoop loop;
    QTimer check;
    check.setInterval(1);
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer deadline;
    deadline.setSingleShot(true);
    QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
    check.start();
    deadline.start(timeoutMs);
    loop.exec();
    return done();
}

// Runs the event loop for `ms`: a measurement window, or the window of a check that something
// does not happen — never a wait for something.
inline void spinFor(int ms)
{
    waitUntil([] { return false; }, ms);
}

// Until a callback has filled `value`.
template<typename T> bool waitFor(const std::optional<T> &value, int timeoutMs = kWaitMs)
{
    return waitUntil([&] { return value.has_value(); }, timeoutMs);
}

// Until `spy` has recorded at least `count` signals (counting those already recorded).
inline bool waitForCount(const QSignalSpy &spy, qsizetype count, int timeoutMs = kWaitMs)
{
    return waitUntil([&] { return spy.count() >= count; }, timeoutMs);
}

// Until the bytes of the signals `received` records (a Link::received spy, emptied as it goes),
// appended to `got`, come to at least `size`.
inline bool collectBytes(QSignalSpy &received, QByteArray &got, qsizetype size,
                         int timeoutMs = kWaitMs)
{
    return waitUntil(
        [&] {
            for (; !received.isEmpty(); received.removeFirst())
                got += received.first().value(0).toByteArray();
            return got.size() >= size;
        },
        timeoutMs);
}

inline bool waitForState(const link::Link &link, link::LinkState state, int timeoutMs = kWaitMs)
{
    return waitUntil([&] { return link.state() == state; }, timeoutMs);
}

} // namespace vt::test
