// Shared by the end-to-end benchmarks against a valvetune-sim process (session_bench.cpp,
// wire_bench.cpp): the simulator on a pty read up to its "listening on" line, an event-loop
// spin with a deadline, and the libmodbus master that serves as their baseline.
#pragma once

#include "access/hcs_rows.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QProcess>
#include <QStringList>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <functional>
#include <modbus/modbus.h>
#include <vector>

namespace vt::bench {

inline bool spin(const std::function<bool()> &done, int timeoutMs)
{
    QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    }
    return true;
}

// valvetune-sim with `args` (e.g. --device dma-pn-v51 --pty); terminated when destroyed.
struct SimProcess
{
    QProcess process;
    QString pty;

    bool start(const QStringList &args)
    {
        process.setProgram(QStringLiteral(VT_SIM_PATH));
        process.setArguments(args);
        process.start();
        QDeadlineTimer deadline(10'000);
        while (!process.canReadLine()) {
            if (deadline.hasExpired())
                return false;
            process.waitForReadyRead(200);
        }
        const QString line = QString::fromUtf8(process.readLine()).trimmed();
        pty = line.section(QLatin1Char(' '), 2);
        return line.startsWith(QLatin1String("listening on "));
    }
    // Stops the simulator; --wire: the requests it refused and the collisions it saw, from its
    // closing line "wire: N requests refused, M collisions" (-1 when it said none).
    struct WireCounts
    {
        int refused = -1;
        int collisions = -1;
    };
    WireCounts stopAndCountWire()
    {
        process.terminate();
        process.waitForFinished(5000);
        const QString said = QString::fromUtf8(process.readAllStandardError());
        WireCounts counts;
        const qsizetype at = said.indexOf(QLatin1String(" requests refused, "));
        if (at < 0)
            return counts;
        const qsizetype from = said.lastIndexOf(QLatin1Char(' '), at - 1) + 1;
        counts.refused = said.mid(from, at - from).toInt();
        const qsizetype after = at + qsizetype(sizeof(" requests refused, ") - 1);
        counts.collisions = said.mid(after, said.indexOf(QLatin1Char(' '), after) - after).toInt();
        return counts;
    }
    ~SimProcess()
    {
        process.terminate();
        if (!process.waitForFinished(5000))
            process.kill();
    }
};

// libmodbus reads `blocks` of `units` `rounds` times; seconds per round, -1 when it cannot
// open the pty. libmodbus sends the next request as soon as an answer is complete; with
// `silenceUs` > 0 the caller keeps the silent interval after each answer, as an application on
// a strict RS-485 line must (Modbus over Serial Line §2.5.1.1).
inline double libmodbusReadAll(const QString &pty, int baud,
                               const std::vector<dev::access::HcsBlock> &blocks,
                               const std::vector<int> &units, int rounds, long silenceUs = 0)
{
    modbus_t *ctx = modbus_new_rtu(pty.toLocal8Bit().constData(), baud, 'E', 8, 1);
    if (!ctx || modbus_connect(ctx) != 0) {
        std::fprintf(stderr, "libmodbus cannot open %s\n", qPrintable(pty));
        if (ctx)
            modbus_free(ctx);
        return -1;
    }
    modbus_set_response_timeout(ctx, 1, 0);
    std::uint16_t dest[8];
    const timespec gap{0, silenceUs * 1000};
    // The line may have carried the previous master's last answer a moment ago: the first
    // request keeps the silent interval too (outside the time measured).
    if (silenceUs > 0)
        clock_nanosleep(CLOCK_MONOTONIC, 0, &gap, nullptr);
    QElapsedTimer timer;
    timer.start();
    for (int round = 0; round < rounds; ++round) {
        for (const int unit : units) {
            modbus_set_slave(ctx, unit);
            for (const auto &block : blocks) {
                const int count = static_cast<int>(block.rows.size());
                if (modbus_read_registers(ctx, block.firstId, count, dest) != count)
                    std::fprintf(stderr, "libmodbus: unit %d block %u failed: %s\n", unit,
                                 block.firstId, modbus_strerror(errno));
                if (silenceUs > 0)
                    clock_nanosleep(CLOCK_MONOTONIC, 0, &gap, nullptr);
            }
        }
    }
    const double seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9 / rounds;
    modbus_close(ctx);
    modbus_free(ctx);
    return seconds;
}

} // namespace vt::bench
