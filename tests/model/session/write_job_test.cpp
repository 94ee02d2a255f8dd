// Safe writes: range check before sending, only changed values, pacing from
// the dictionary (DMA Profinet manual §3.4.1: ≥ 30 ms), read back, per-parameter result, and a
// write cut in the middle that resumes to completion.
#include "model/session/write_job.h"
#include "sim_rig.h"

#include <QSignalSpy>

namespace vt::test {
namespace {

using model::AuditOrigin;
using model::WriteItem;
using model::WriteJob;
using model::WriteStatus;

std::vector<WriteItem> items(const dev::Dictionary &dict,
                             std::initializer_list<std::pair<const char *, double>> values)
{
    std::vector<WriteItem> out;
    for (const auto &[name, raw] : values) {
        WriteItem item;
        item.row = dict.find(name);
        EXPECT_TRUE(item.row) << name;
        item.value = raw;
        out.push_back(item);
    }
    return out;
}

bool runJob(WriteJob &job, bool resume = false)
{
    QSignalSpy finished(&job, &WriteJob::finished);
    resume ? job.resume() : job.start();
    return finished.wait(kWaitMs) || finished.count() > 0;
}

// Sim-clock times (µs) at which FC 6 requests left the master.
struct WriteTimes
{
    std::vector<qint64> sessionNs;
    std::vector<std::int64_t> simUs;
};

void recordWrites(SimRig &c, WriteTimes &times)
{
    QObject::connect(&c.session(), &model::Session::frameSent,
                     [&c, &times](const QByteArray &bytes, int, qint64 ns) {
                         if (bytes.size() > 1 && bytes[1] == 6) {
                             times.sessionNs.push_back(ns);
                             times.simUs.push_back(c.simEndpoint()->clock().nowUs());
                         }
                     });
}

TEST(WriteJob, WritesVerifiesAndTheSimulatorHoldsTheValue)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    // The editor's scenario on the session level: C1.07 = 1.000 V is raw 1000.
    WriteJob job(c->access(), c->address(), c->dictionary(),
                 items(c->dictionary(), {{"C1.07", 1000}, {"r1.01", 120}}), AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_TRUE(job.complete());
    for (const WriteItem &item : job.items()) {
        EXPECT_EQ(item.status, WriteStatus::Verified)
            << item.row->name << ": " << item.reason.text().toStdString();
        EXPECT_EQ(storedRaw(c->simModule(), *item.row), dev::rawNumber(item.value))
            << item.row->name;
    }
}

TEST(WriteJob, OutOfRangeAndReadOnlyNeverLeaveTheMaster)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    QSignalSpy sent(&c->session(), &model::Session::frameSent);
    const double before = storedRaw(c->simModule(), *c->dictionary().find("C1.07"));
    WriteJob job(
        c->access(), c->address(), c->dictionary(),
        items(c->dictionary(), {{"C1.07", 10000}, {"C1.07", -1}, {"d1.10", 5}, {"C1.17", 4001}}),
        AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_EQ(sent.count(), 0);
    for (const WriteItem &item : job.items())
        EXPECT_EQ(item.status, WriteStatus::RefusedLocally) << item.row->name;
    const QString english = writeReasonText(job.items()[0], dev::Language::English);
    EXPECT_NE(english.indexOf(QStringLiteral("9.999")), -1) << english.toStdString();
    // The dictionary's refusal stays in both languages until it is shown.
    const QString german = writeReasonText(job.items()[0], dev::Language::German);
    EXPECT_NE(german.indexOf(QStringLiteral("9,999")), -1) << german.toStdString();
    EXPECT_EQ(storedRaw(c->simModule(), *c->dictionary().find("C1.07")), before);
}

TEST(WriteJob, SendsOnlyChangedValues)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    auto list = items(c->dictionary(), {{"C1.07", 0}, {"C1.08", 500}});
    list[0].before = 0.0; // the device already holds it
    list[1].before = 0.0;
    WriteTimes times;
    recordWrites(*c, times);
    WriteJob job(c->access(), c->address(), c->dictionary(), list, AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_EQ(job.items()[0].status, WriteStatus::Unchanged);
    EXPECT_EQ(job.items()[1].status, WriteStatus::Verified);
    EXPECT_EQ(times.sessionNs.size(), 1u);
}

TEST(WriteJob, PacingHoldsOnTheSimulatedClockAndTheEepromNeverRefuses)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->dictionary().writePacingMs, 30);
    WriteTimes times;
    recordWrites(*c, times);
    WriteJob job(
        c->access(), c->address(), c->dictionary(),
        items(c->dictionary(),
              {{"C1.07", 100}, {"C1.08", 200}, {"C2.07", 300}, {"C2.08", 400}, {"r1.01", 10}}),
        AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_TRUE(job.complete());
    ASSERT_EQ(times.simUs.size(), 5u);
    for (std::size_t i = 1; i < times.simUs.size(); ++i) {
        EXPECT_GE(times.sessionNs[i] - times.sessionNs[i - 1], 30'000'000) << i;
        // The simulated clock advances in 1 ms ticks behind the wall clock.
        EXPECT_GE(times.simUs[i] - times.simUs[i - 1], 29'000) << i;
    }
}

TEST(WriteJob, WithoutPacingTheBusyEepromRefusesSoPacingMatters)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    model::WriteOptions unpaced;
    unpaced.pacingMs = 0;
    unpaced.verify = false;
    WriteJob job(c->access(), c->address(), c->dictionary(),
                 items(c->dictionary(), {{"C1.07", 100}, {"C1.08", 200}, {"C2.07", 300}}),
                 AuditOrigin::Editor, unpaced);
    ASSERT_TRUE(runJob(job));
    int refused = 0;
    for (const WriteItem &item : job.items())
        refused += item.status == WriteStatus::Refused && item.exceptionCode == 4;
    EXPECT_GE(refused, 1); // DMA: exception 4 while the EEPROM is busy
}

TEST(WriteJob, DeviceRefusalIsReportedWithTheDevicesReason)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    const dev::ParamMeta *row = c->dictionary().find("C1.07");
    ASSERT_TRUE(row);
    // Pretend the dictionary allowed more than the module does: a copy of the row with a wider
    // range.
    dev::ParamMeta wide = *row;
    wide.max = 32000;
    std::vector<WriteItem> list(1);
    list[0].row = &wide;
    list[0].value = 20000.0;
    WriteJob job(c->access(), c->address(), c->dictionary(), list, AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_EQ(job.items()[0].status, WriteStatus::Refused);
    EXPECT_EQ(job.items()[0].exceptionCode, 3);
    EXPECT_FALSE(writeReasonText(job.items()[0], dev::Language::English).isEmpty());
    // The device's refusal reaches the view in the language shown, not flattened to English.
    const dev::LocalText &refusal = job.items()[0].deviceText;
    EXPECT_TRUE(refusal.complete());
    EXPECT_EQ(writeReasonText(job.items()[0], dev::Language::German),
              QString::fromStdString(refusal.de));
    EXPECT_NE(refusal.de, refusal.en);
}

TEST(WriteJob, ACutMidWriteLeavesAnExactRecordAndResumeFinishesIt)
{
    link::FaultSpec cut;
    cut.cutAfterFrames =
        9; // two rows verified (4 frames each), the third row's write request goes out
    model::SessionOptions options;
    options.turnaround = std::chrono::milliseconds(50);
    auto c = openSim({"dma-pn-v51", 1, {}, cut, options});
    ASSERT_TRUE(c);
    auto list =
        items(c->dictionary(),
              {{"C1.07", 111}, {"C1.08", 222}, {"C2.07", 333}, {"C2.08", 444}, {"r1.01", 55}});
    std::vector<double> before;
    for (WriteItem &item : list) {
        before.push_back(storedRaw(c->simModule(), *item.row));
        item.before = before.back();
    }
    WriteJob job(c->access(), c->address(), c->dictionary(), list, AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));
    EXPECT_FALSE(job.complete());
    // The record says exactly what is on the device.
    int verified = 0, uncertain = 0, notSent = 0;
    for (std::size_t i = 0; i < job.items().size(); ++i) {
        const WriteItem &item = job.items()[i];
        const double stored = storedRaw(c->simModule(), *item.row);
        switch (item.status) {
        case WriteStatus::Verified:
            ++verified;
            EXPECT_EQ(stored, dev::rawNumber(item.value)) << item.row->name;
            break;
        case WriteStatus::NotSent:
            ++notSent;
            EXPECT_EQ(stored, before[i]) << item.row->name;
            break;
        case WriteStatus::Uncertain: ++uncertain; break;
        default: ADD_FAILURE() << item.row->name << " ended " << model::writeStatusKey(item.status);
        }
    }
    EXPECT_EQ(verified, 2);
    EXPECT_EQ(uncertain, 1);
    EXPECT_EQ(notSent, 2);

    // Reconnect without the cut and resume.
    c->faultLink()->setSpec(link::FaultSpec{});
    ASSERT_TRUE(c->open());
    ASSERT_TRUE(runJob(job, true));
    EXPECT_TRUE(job.complete());
    for (const WriteItem &item : job.items()) {
        EXPECT_EQ(item.status, WriteStatus::Verified) << item.row->name;
        EXPECT_EQ(storedRaw(c->simModule(), *item.row), dev::rawNumber(item.value))
            << item.row->name;
    }
}

} // namespace
} // namespace vt::test
