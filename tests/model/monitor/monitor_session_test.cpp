// The monitor's model: samples arrive at the requested rate (session clock),
// memory stays within the store's bound after a long run, journal texts, merged CSV export.
#include "model/monitor/monitor_export.h"
#include "model/monitor/monitor_session.h"
#include "sim_rig.h"

#include <QBuffer>
#include <cmath>

namespace vt::test {
namespace {

using model::MonitorSession;

TEST(MonitorSession, DefaultChannelsAreDesiredActualAndSolenoidCurrents)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorSession session;
    session.setConnection(rig->connection.get(), rig->modules);
    QStringList names;
    for (const dev::ParamMeta *row : session.channels(rig->module().address))
        names.append(QString::fromStdString(row->name));
    EXPECT_EQ(names, (QStringList{"d1.10", "d1.11", "d1.07", "d1.08", "d1.09"}));
    EXPECT_FALSE(session.isRunning()); // polling starts with start(), not on setConnection
    EXPECT_TRUE(session.store(rig->module().address)->isEmpty());
    session.clearConnection();
}

TEST(MonitorSession, SamplesArriveAtTheRequestedRate)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorSession session;
    session.setConnection(rig->connection.get(), rig->modules);
    const int module = rig->module().address;
    constexpr double kHz = 100;
    session.setRate(kHz);
    session.start();
    const model::SampleStore *store = session.store(module);
    ASSERT_TRUE(waitUntil([&] { return store->size() >= 150; }, kWaitMs));
    session.stop();
    // Rate from the samples' own session timestamps; the simulator runs in real time, so allow
    // for a loaded machine.
    const double span = store->lastTime() - store->firstTime();
    ASSERT_GT(span, 0);
    const double measured = static_cast<double>(store->size() - 1) / span;
    EXPECT_GT(measured, kHz * 0.8) << measured;
    EXPECT_LT(measured, kHz * 1.2) << measured;
    EXPECT_GT(session.scheduler()->achievedRate(module), kHz * 0.7);
    // Values are in display units: the currents and voltages of an idle module are small.
    for (int c = 0; c < store->channelCount(); ++c)
        EXPECT_LT(std::abs(store->valueAt(c, store->size() - 1)), 100.0);
    session.clearConnection();
}

TEST(MonitorSession, MemoryStaysWithinTheStoreBoundAfterALongRun)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorSession session;
    constexpr qsizetype kRows = 400; // small, so "long" (many times the capacity) is fast
    session.setStoreCapacity(kRows);
    session.setConnection(rig->connection.get(), rig->modules);
    const int module = rig->module().address;
    const model::SampleStore *store = session.store(module);
    const qint64 bytesEmpty = session.memoryBytes();
    EXPECT_EQ(bytesEmpty, store->memoryBytes());
    EXPECT_GE(bytesEmpty, model::SampleStore::ringBytes(5, kRows));
    EXPECT_FALSE(store->isResident()); // connecting alone does not take the ring's memory
    session.setRate(0);                // as fast as the link allows
    session.start();
    EXPECT_TRUE(store->isResident()); // starting does, all at once (issue #21)
    ASSERT_TRUE(waitUntil([&] { return session.samples(module) >= 20 * kRows; }, kWaitMs));
    session.stop();
    EXPECT_EQ(store->size(), kRows);
    EXPECT_GE(store->droppedCount(), static_cast<quint64>(19 * kRows));
    EXPECT_EQ(session.memoryBytes(), bytesEmpty); // fixed at construction, however long it runs
    session.clearConnection();
}

TEST(MonitorSession, ClearConnectionStopsPollingAndKeepsTheRecording)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorSession session;
    QSignalSpy running(&session, &MonitorSession::runningChanged);
    session.setConnection(rig->connection.get(), rig->modules);
    session.setRate(200);
    session.start();
    const model::SampleStore *store = session.store(rig->module().address);
    ASSERT_TRUE(waitUntil([&] { return store->size() >= 10; }, kWaitMs));
    session.clearConnection();
    EXPECT_FALSE(session.isRunning());
    ASSERT_EQ(running.count(), 2);
    EXPECT_FALSE(running.back().front().toBool());
    const qsizetype rows = store->size();
    spinFor(100); // nothing may arrive any more; waiting is the point of this check
    EXPECT_EQ(store->size(), rows);
    EXPECT_EQ(session.store(rig->module().address), store);
}

TEST(TuningJournal, MarkerTextsShowOldAndNewValueInTheLanguage)
{
    const dev::Dictionary &dict = *dictionaries().find("dma-pn-v51");
    model::WriteItem item;
    item.row = dict.find("A1.01");
    ASSERT_TRUE(item.row);
    item.before = 800.0;
    item.value = 1000.0;
    item.status = model::WriteStatus::Verified;
    EXPECT_EQ(model::writeMarkerText(item, dev::Language::English),
              QStringLiteral("A1.01 0.800 V → 1.000 V"));
    EXPECT_EQ(model::writeMarkerText(item, dev::Language::German),
              QStringLiteral("A1.01 0,800 V → 1,000 V"));
    item.before.reset();
    EXPECT_EQ(model::writeMarkerText(item, dev::Language::English),
              QStringLiteral("A1.01 → 1.000 V"));

    model::TuningJournal journal(3);
    model::WriteItem unchanged = item;
    unchanged.status = model::WriteStatus::Unchanged;
    model::WriteItem refused = item;
    refused.status = model::WriteStatus::Refused;
    EXPECT_EQ(journal.addWrites(1.0, 1, {item, unchanged, refused}, dev::Language::English, false),
              1);
    EXPECT_EQ(journal.addWrites(2.0, 2, {item}, dev::Language::English, true), 1);
    EXPECT_EQ(journal.markers().back().text, QStringLiteral("module 2: A1.01 → 1.000 V"));
    for (int i = 0; i < 5; ++i)
        journal.add(3.0 + i, QStringLiteral("x"));
    EXPECT_EQ(journal.markers().size(), 3u); // bounded
    EXPECT_EQ(journal.markersIn(5.5, 7.5).size(), 2u);
}

TEST(MonitorSession, CsvOfTwoModulesMergesTheirRowsInTimeOrder)
{
    auto rig = connectSim("dma-pn-v51", 2);
    ASSERT_TRUE(rig);
    ASSERT_EQ(rig->modules.size(), 2u);
    MonitorSession session;
    session.setConnection(rig->connection.get(), rig->modules);
    const int a = rig->module(0).address, b = rig->module(1).address;
    session.setChannels(b, {&rig->row("d1.11", 1)});
    session.setRate(50);
    session.start();
    ASSERT_TRUE(waitUntil(
        [&] { return session.store(a)->size() >= 10 && session.store(b)->size() >= 10; }, kWaitMs));
    session.stop();
    model::WriteItem item;
    item.row = &rig->row("A1.01", 1);
    item.before = 0.0;
    item.value = 500.0;
    item.status = model::WriteStatus::Verified;
    session.journalWrites(b, {item});

    QBuffer buffer;
    buffer.open(QIODevice::ReadWrite);
    QString error;
    ASSERT_TRUE(model::writeMonitorCsv(session, buffer, -1e300, 1e300, &error))
        << error.toStdString();
    buffer.seek(0);
    auto back = model::SampleStore::readCsv(buffer, &error);
    ASSERT_TRUE(back) << error.toStdString();
    ASSERT_EQ(back->channelCount(), 6);
    EXPECT_EQ(back->channels().front().id, QStringLiteral("%1/d1.10").arg(a));
    EXPECT_EQ(back->channels().back().id, QStringLiteral("%1/d1.11").arg(b));
    EXPECT_EQ(back->size(), session.store(a)->size() + session.store(b)->size());
    for (qsizetype i = 1; i < back->size(); ++i)
        ASSERT_LE(back->timeAt(i - 1), back->timeAt(i));
    ASSERT_EQ(back->markers().size(), 1u);
    EXPECT_EQ(back->markers().front().text,
              QStringLiteral("module %1: A1.01 0.000 V → 0.500 V").arg(b));
    session.clearConnection();
}

} // namespace
} // namespace vt::test
