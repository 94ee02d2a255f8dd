// RecordingLink: a synchronous in-test Link for FaultLink tests. It opens at once, records what is
// sent and lets the test inject received chunks and failures, so fault schedules can be checked
// frame by frame without an event loop.
#pragma once

#include "transports/link.h"

#include <vector>

namespace vt::test {

class RecordingLink : public vt::link::Link
{
public:
    void open() override { setState(vt::link::LinkState::Open); }
    void close() override { setState(vt::link::LinkState::Closed); }
    void send(const QByteArray &bytes) override { sent.push_back(bytes); }
    QString description() const override { return QStringLiteral("fake"); }

    void inject(const QByteArray &bytes) { emit received(bytes); }
    void breakDown(const QString &reason)
    {
        setState(vt::link::LinkState::Failed);
        emit failed(reason);
    }

    std::vector<QByteArray> sent;
};

} // namespace vt::test
