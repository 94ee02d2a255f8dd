// Helpers of the valvetune-sim end-to-end tests (sim_cli_test.cpp, sim_can_test.cpp): the
// simulator as a child process read up to its "listening on" line, one-shot runs of a program
// (mbpoll, socat, the simulator itself) with bounded waits, and what a fresh in-process node
// holds. No sleeps: every wait is a QProcess wait with a deadline.
#pragma once

#include "sim/node_config.h"
#include "wait_bound.h"

#include <QDeadlineTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStringList>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include <string>

namespace vt::simtest {

using test::kWaitMs;

// A child process (valvetune-sim by default); SIGTERM (then SIGKILL) when the test is done.
// `inChild` runs between fork and exec (e.g. to let a descriptor survive the exec).
class Sim
{
public:
    explicit Sim(const QStringList &args, std::function<void()> inChild = {},
                 const QString &program = QStringLiteral(VT_SIM_PATH))
    {
        m_process.setProgram(program);
        m_process.setArguments(args);
        if (inChild)
            m_process.setChildProcessModifier(inChild);
        m_process.start();
    }
    ~Sim()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(kWaitMs)) {
            m_process.kill();
            m_process.waitForFinished(kWaitMs);
        }
    }
    Sim(const Sim &) = delete;
    Sim &operator=(const Sim &) = delete;

    // What follows "listening on " on the first stdout line; empty when none came in time.
    QString listening()
    {
        const QDeadlineTimer deadline(kWaitMs);
        while (!m_process.canReadLine()) {
            if (deadline.hasExpired() || m_process.state() == QProcess::NotRunning)
                return {};
            m_process.waitForReadyRead(
                static_cast<int>(std::max<qint64>(1, deadline.remainingTime())));
        }
        const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
        const QString prefix = QStringLiteral("listening on ");
        return line.startsWith(prefix) ? line.mid(prefix.size()) : QString();
    }
    // Reads stderr until it contains `text` (true) or the deadline / the process ends (false);
    // everything read so far stays in stderrSeen().
    bool waitForStderr(const QString &text)
    {
        m_process.setReadChannel(QProcess::StandardError);
        const QDeadlineTimer deadline(kWaitMs);
        for (;;) {
            m_stderr += QString::fromUtf8(m_process.readAllStandardError());
            if (m_stderr.contains(text))
                return true;
            if (deadline.hasExpired() || m_process.state() == QProcess::NotRunning)
                return false;
            m_process.waitForReadyRead(
                static_cast<int>(std::max<qint64>(1, deadline.remainingTime())));
        }
    }
    const QString &stderrSeen() const { return m_stderr; }
    QString stderrText() { return m_stderr + QString::fromUtf8(m_process.readAllStandardError()); }
    QProcess &process() { return m_process; }

private:
    QProcess m_process;
    QString m_stderr;
};

struct ProcessRun
{
    bool finished = false;
    int code = -1;
    QString out, err;
};

inline ProcessRun run(const QString &program, const QStringList &args)
{
    QProcess p;
    p.start(program, args);
    ProcessRun r;
    r.finished = p.waitForFinished(kWaitMs);
    if (!r.finished)
        p.kill();
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

inline QString mbpoll()
{
    return QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
}

// mbpoll's "[ref]: \tvalue" lines, values as the 16-bit register words.
inline std::map<int, std::uint16_t> registers(const QString &out)
{
    std::map<int, std::uint16_t> values;
    static const QRegularExpression line(QStringLiteral(R"(^\[(\d+)\]:\s+(-?\d+))"),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        values[m.captured(1).toInt()] = static_cast<std::uint16_t>(m.captured(2).toInt());
    }
    return values;
}

// A fresh in-process node: what the simulator's modules hold before anyone writes.
inline std::uint16_t freshWord(const std::string &family, std::size_t modules, std::size_t index,
                               int id)
{
    dev::sim::SimClock clock;
    auto node = dev::sim::makeNode(clock, family, modules);
    EXPECT_TRUE(node.ok());
    return node.ok() ? (*node)->module(index).storage().word(id) : 0;
}

// The parameter ID of `name` in `family` (-1 when the family has no such row).
inline int paramId(const std::string &family, const std::string &name)
{
    dev::sim::SimClock clock;
    auto node = dev::sim::makeNode(clock, family, 1);
    const dev::ParamMeta *meta = node.ok() ? (*node)->module(0).storage().find(name) : nullptr;
    return meta && meta->id ? *meta->id : -1;
}

inline int lineCount(const QString &text)
{
    return static_cast<int>(text.count(QLatin1Char('\n')));
}

} // namespace vt::simtest
