// Bounded waits for the transport tests: they run the event loop until a condition holds or the
// timeout passes (QTest::qWaitFor, what QTRY_* uses), so no test ever sleeps a fixed time.
#pragma once

#include "transports/link.h"

#include <QSignalSpy>
#include <QTest>

namespace vt::test {

inline constexpr int kTimeoutMs = 5000;

inline bool waitForCount(const QSignalSpy &spy, qsizetype count, int timeoutMs = kTimeoutMs)
{
    return QTest::qWaitFor([&] { return spy.count() >= count; }, timeoutMs);
}

inline bool waitForState(const vt::link::Link &link, vt::link::LinkState state,
                         int timeoutMs = kTimeoutMs)
{
    return QTest::qWaitFor([&] { return link.state() == state; }, timeoutMs);
}

} // namespace vt::test
