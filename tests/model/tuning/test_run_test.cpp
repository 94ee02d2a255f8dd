// The workbench's test engine (model/tuning/test_run.h) against the built-in simulator: it refuses
// before writing anything, records the set value as acknowledged, and every way a test ends puts
// the set value and its source back (ARCHITECTURE.md "Trust rules").
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "model/tuning/test_run.h"
#include "sim_rig.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

using test::SimRig;

constexpr int kTestWaitMs = 20'000;

SignalSpec upStep(double from, double to, double hold)
{
    SignalSpec s;
    s.kind = SignalKind::Step;
    s.from = from;
    s.to = to;
    s.hold = hold;
    return s;
}

struct Bench
{
    std::unique_ptr<SimRig> rig = test::connectSim({"dma-pn-v51", 1, {}, {}, {}});

    bool write(const char *name, double raw)
    {
        std::optional<Outcome> done;
        rig->access().write(rig->module().address, rig->row(name), dev::RawValue{raw},
                            Priority::User, std::nullopt, [&](const Outcome &o) { done = o; });
        if (!test::waitFor(done))
            return false;
        // DMA Profinet manual §3.4.1: an EEPROM write needs up to 25 ms; the module refuses the
        // next one before (the product paces its own writes, WriteJob).
        if (rig->row(name).persistence != dev::Persistence::Volatile)
            test::spinFor(rig->module().dictionary->writePacingMs + 5);
        EXPECT_EQ(done->status, OutcomeStatus::Ok) << name << ": " << done->reason.toStdString();
        return done->status == OutcomeStatus::Ok;
    }
    double read(const char *name) { return rig->read(name).value_or(NAN); }

    TestRunSetup setup(const SignalSpec &spec)
    {
        TestRunSetup s =
            TestRun::setupFor(rig->module(), rig->row("A1.01"), *TestSignal::make(spec));
        return s;
    }

    TestOutcome run(TestRun &test)
    {
        std::optional<TestOutcome> outcome;
        QObject::connect(&test, &TestRun::finished, &test,
                         [&](const TestOutcome &o) { outcome = o; });
        test.start();
        EXPECT_TRUE(test::waitFor(outcome, kTestWaitMs));
        TestOutcome none;
        none.end = TestEnd::LinkLost;
        none.reason = QStringLiteral("no end");
        return outcome.value_or(none);
    }
};

TEST(TestRun, AStepRecordsTheAcknowledgedSetValueAndPutsItBack)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 1000)); // 1.000 V before the test
    TestRun test(b.rig->access(), b.setup(upStep(3, 5, 0.2)));
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Finished) << outcome.reason.toStdString();
    EXPECT_TRUE(outcome.restored);
    const TestRecording &r = test.recording();
    ASSERT_EQ(r.setValue.y.size(), 2u); // only changes are written
    EXPECT_DOUBLE_EQ(r.setValue.y[0], 3.0);
    EXPECT_DOUBLE_EQ(r.setValue.y[1], 5.0);
    EXPECT_DOUBLE_EQ(r.setValue.t[0], 0);
    EXPECT_GT(r.setValue.t[1], 0.19);
    ASSERT_GE(r.channels.size(), 2u); // the monitor's channels: d1.10, d1.11, the currents
    EXPECT_GT(r.channels[1].t.size(), 5u);
    EXPECT_GE(r.channels[1].t.back(), 0.39);
    EXPECT_GT(r.sampleRateHz(), 10);
    // d1.10 is the set value after the ramps: it saw the step.
    EXPECT_DOUBLE_EQ(r.channels[0].y.back(), 5.0);
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 1000);
    ASSERT_EQ(outcome.restore.size(), 1u);
    EXPECT_EQ(outcome.restore[0].status, WriteStatus::Verified);
}

// The session log has every set value the test wrote (no read back: "written") and the verified
// restore, under the workbench; the CLI's test command names itself (cli_audit_test.cpp).
TEST(TestRun, EveryWriteOfATestIsInTheSessionLog)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("test"), dir.path());
    const AuditLog::Scope scope(log);
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 1000));
    TestRun test(b.rig->access(), b.setup(upStep(3, 5, 0.2)));
    const TestOutcome outcome = b.run(test);
    ASSERT_EQ(outcome.end, TestEnd::Finished) << outcome.reason.toStdString();

    const AuditLogContents read = readAuditLog(log.path());
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    ASSERT_EQ(read.entries.size(), 3u); // 3 V, 5 V, then 1 V back
    for (const AuditEntry &e : read.entries) {
        EXPECT_EQ(e.row, QStringLiteral("A1.01"));
        EXPECT_EQ(e.origin, QStringLiteral("workbench"));
    }
    EXPECT_EQ(read.entries[0].status, QStringLiteral("written"));
    EXPECT_EQ(read.entries[0].newRaw, QStringLiteral("3000"));
    EXPECT_EQ(read.entries[0].oldRaw, QStringLiteral("1000"));
    EXPECT_EQ(read.entries[1].status, QStringLiteral("written"));
    EXPECT_EQ(read.entries[1].newRaw, QStringLiteral("5000"));
    EXPECT_EQ(read.entries[2].status, QStringLiteral("verified"));
    EXPECT_EQ(read.entries[2].newRaw, QStringLiteral("1000"));
}

// A loaded machine may hold the test back longer than a level lasts: the level is still written
// and held, never skipped.
TEST(TestRun, ALateCycleNeverSkipsALevel)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    SignalSpec spec = upStep(3, 5, 0.05);
    spec.direction = StepDirection::Both;
    TestRun test(b.rig->access(), b.setup(spec));
    bool stalled = false;
    QObject::connect(&test, &TestRun::sampled, &test, [&] {
        if (!stalled && test.recording().setValue.y.size() == 2) {
            stalled = true;
            QElapsedTimer busy; // the GUI thread busy for two levels' time
            busy.start();
            while (busy.elapsed() < 120) {
            }
        }
    });
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Finished);
    ASSERT_EQ(test.recording().setValue.y.size(), 3u);
    EXPECT_DOUBLE_EQ(test.recording().setValue.y[2], 3.0);
    const double held = test.recording().channels[0].t.back() - test.recording().setValue.t[2];
    EXPECT_GE(held, 0.045);
}

TEST(TestRun, TheSourceIsCheckedFirstAndNothingIsWrittenWhenItDiffers)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 0));
    ASSERT_TRUE(b.write("A1.01", 1000));
    QSignalSpy sent(&b.rig->session(), &Session::frameSent);
    TestRun test(b.rig->access(), b.setup(upStep(3, 5, 0.2)));
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Refused);
    EXPECT_TRUE(outcome.needsSource);
    EXPECT_TRUE(outcome.reason.contains("E17")) << outcome.reason.toStdString();
    EXPECT_TRUE(test.recording().setValue.t.empty());
    EXPECT_EQ(sent.count(), 2); // reading E17 and A1.01, nothing else
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 1000);
}

TEST(TestRun, ASwitchedSourceGoesBackAfterTheTest)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 0));
    ASSERT_TRUE(b.write("A1.01", 0));
    TestRunSetup setup = b.setup(upStep(3, 5, 0.1));
    setup.switchSource = true;
    TestRun test(b.rig->access(), setup);
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Finished) << outcome.reason.toStdString();
    EXPECT_TRUE(outcome.restored);
    EXPECT_EQ(test.recording().setValue.y.size(), 2u);
    EXPECT_DOUBLE_EQ(b.read("E17"), 0);
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 0);
    ASSERT_EQ(outcome.restore.size(), 2u);
    EXPECT_EQ(outcome.restore[0].row->name, "A1.01"); // the set value before its source
    EXPECT_EQ(outcome.restore[1].row->name, "E17");
}

TEST(TestRun, ASignalOutsideTheRowsRangeIsRefusedBeforeAnythingIsSent)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    const quint64 before = b.rig->session().counters().requests;
    TestRun test(b.rig->access(), b.setup(upStep(3, 12, 0.1)));
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Refused);
    EXPECT_TRUE(outcome.reason.contains("A1.01")) << outcome.reason.toStdString();
    EXPECT_EQ(b.rig->session().counters().requests, before);
}

TEST(TestRun, StopEndsTheTestAndRestores)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 500));
    TestRun test(b.rig->access(), b.setup(upStep(3, 5, 5)));
    QObject::connect(&test, &TestRun::sampled, &test, [&] {
        if (test.recording().cycles == 3)
            test.stop();
    });
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::Stopped);
    EXPECT_TRUE(outcome.restored);
    EXPECT_LT(test.recording().channels[0].t.back(), 4.0);
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 500);
}

TEST(TestRun, TheTravelWindowStopsATest)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    // Feedback from the bus (C1.09 = 0, no offset), held at 0 V: far outside 8..9 V ± 0.5 V.
    ASSERT_TRUE(b.write("C1.09", 0));
    ASSERT_TRUE(b.write("C1.11", 0));
    ASSERT_TRUE(b.write("A1.02", 0));
    ASSERT_TRUE(b.write("A1.01", 0));
    TestRunSetup setup = b.setup(upStep(8, 9, 2));
    setup.window = 0.5;
    TestRun test(b.rig->access(), setup);
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::WindowExceeded);
    EXPECT_TRUE(outcome.reason.contains("d1.11")) << outcome.reason.toStdString();
    EXPECT_TRUE(outcome.restored);
    EXPECT_LT(test.recording().cycles, 3);
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 0);
}

// DMA Profinet manual §4.5.1.1: a short circuit latches the error (0xB0 bit 11 "Error") and
// switches the outputs off; the test stops on it and still puts the set value back.
TEST(TestRun, AModuleErrorStopsTheTest)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 100));
    TestRunSetup setup = b.setup(upStep(3, 5, 5));
    ASSERT_TRUE(setup.faultRow);
    TestRun test(b.rig->access(), setup);
    QObject::connect(&test, &TestRun::sampled, &test, [&] {
        if (test.recording().cycles == 3) {
            dev::sim::ClosedLoopPlant *plant = b.rig->simModule().closedLoop(1);
            ASSERT_TRUE(plant);
            plant->setSolenoidFault(false, dev::sim::SolenoidFault::ShortCircuit);
        }
    });
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::DeviceError) << key(outcome.end);
    EXPECT_TRUE(outcome.reason.contains(QStringLiteral("0xB0"))) << outcome.reason.toStdString();
    EXPECT_LT(test.recording().channels[0].t.back(), 4.0);
    EXPECT_TRUE(outcome.restored);
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 100);
}

TEST(TestRun, ALostLinkEndsTheTestAndSaysTheSetValueIsNotBack)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    TestRun test(b.rig->access(), b.setup(upStep(3, 5, 5)));
    QObject::connect(&test, &TestRun::sampled, &test, [&] {
        if (test.recording().cycles == 2)
            b.rig->connection->close();
    });
    const TestOutcome outcome = b.run(test);
    EXPECT_EQ(outcome.end, TestEnd::LinkLost) << key(outcome.end);
    EXPECT_FALSE(outcome.restored);
    ASSERT_FALSE(outcome.restore.empty());
    EXPECT_FALSE(isOnDevice(outcome.restore[0].status));
}

} // namespace
} // namespace vt::model
