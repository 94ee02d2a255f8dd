// A Connection to the built-in simulator with its modules identified, as the main window hands
// it to the monitor (MonitorView::setConnection). Waits on signals, bounded; never sleeps.
#pragma once

#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/session/connection.h"
#include "qt_printers.h"

#include <QEventLoop>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <gtest/gtest.h>
#include <memory>
#include <optional>

namespace vt::test {

inline constexpr int kWaitMs = 20'000;

// Runs a real event loop until `done()` holds (checked every millisecond) or the time is up.
// QTest::qWaitFor sleeps 10 ms between event batches, which would throttle the monitor's polling
// and falsify any rate measured under it.
template<typename Predicate> bool spinUntil(Predicate done, int timeoutMs = kWaitMs)
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

// Runs the event loop for `ms` (a measurement window, not a wait for something).
inline void spinFor(int ms)
{
    spinUntil([] { return false; }, ms);
}

inline const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}

struct MonitorRig
{
    std::unique_ptr<model::Connection> connection;
    std::vector<model::ModuleInfo> modules;

    const model::ModuleInfo &module(std::size_t i = 0) const { return modules.at(i); }
    const dev::ParamMeta &row(const char *name, std::size_t i = 0) const
    {
        const dev::ParamMeta *row = module(i).dictionary->find(name);
        EXPECT_TRUE(row) << name;
        return *row;
    }

    // Reads one row of a module (bounded wait); nullopt on failure.
    std::optional<double> read(const char *name, std::size_t i = 0)
    {
        std::optional<model::ReadResult> result;
        connection->access().read(module(i).address, {&row(name, i)}, model::Priority::User,
                                  [&](const model::ReadResult &r) { result = r; });
        if (!spinUntil([&] { return result.has_value(); }, kWaitMs) || !result->complete() ||
            result->values.empty())
            return std::nullopt;
        return dev::rawNumber(result->values.front().value);
    }
};

inline std::unique_ptr<MonitorRig> connectSim(const std::string &family, std::size_t modules = 1,
                                              std::optional<link::FaultSpec> fault = std::nullopt)
{
    auto rig = std::make_unique<MonitorRig>();
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = family;
    spec.sim.modules = modules;
    spec.fault = fault;
    auto made = model::Connection::create(spec, dictionaries());
    if (!made.ok()) {
        ADD_FAILURE() << made.error().toStdString();
        return nullptr;
    }
    rig->connection = std::move(made).value();
    QSignalSpy opened(rig->connection.get(), &model::Connection::opened);
    rig->connection->open();
    if (!opened.wait(kWaitMs)) {
        ADD_FAILURE() << "the simulator did not open";
        return nullptr;
    }
    for (int address : rig->connection->moduleAddresses()) {
        std::optional<model::IdentifyResult> identified;
        rig->connection->access().identify(address,
                                           [&](const model::IdentifyResult &r) { identified = r; });
        if (!spinUntil([&] { return identified.has_value(); }, kWaitMs) || !identified->ok) {
            ADD_FAILURE() << "module " << address << " not identified";
            return nullptr;
        }
        rig->modules.push_back(identified->module);
    }
    return rig;
}

} // namespace vt::test
