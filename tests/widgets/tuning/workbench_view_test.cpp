// The workbench dock as a person uses it (widgets/tuning/workbench_view.h), on the built-in
// simulator: asked before anything moves, a run with its results, the source switched only after
// a second question and put back, Stop, and runs saved and loaded again.
#include "actuator_answer.h"
#include "model/text_language.h"
#include "sim_rig.h"
#include "widgets/tuning/signal_form.h"
#include "widgets/tuning/workbench_view.h"

#include <QTableWidget>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

constexpr int kRunWaitMs = 20'000;

model::SignalSpec step(double hold)
{
    model::SignalSpec s;
    s.kind = model::SignalKind::Step;
    s.from = 3;
    s.to = 5;
    s.hold = hold;
    s.direction = model::StepDirection::Both;
    return s;
}

struct Bench
{
    std::unique_ptr<test::SimRig> rig = test::connectSim({"dma-pn-v51", 1, {}, {}, {}});
    WorkbenchView view;

    Bench()
    {
        view.resize(1200, 500);
        view.setConnection(&rig->access(), rig->modules);
    }
    bool write(const char *name, double raw)
    {
        std::optional<model::Outcome> done;
        rig->access().write(rig->module().address, rig->row(name), dev::RawValue{raw},
                            model::Priority::User, std::nullopt,
                            [&](const model::Outcome &o) { done = o; });
        const bool ok = test::waitFor(done) && done->status == model::OutcomeStatus::Ok;
        // DMA Profinet manual §3.4.1: the module takes the next EEPROM write after ~25 ms.
        test::spinFor(rig->module().dictionary->writePacingMs + 5);
        return ok;
    }
    bool runOnce(std::size_t runs)
    {
        view.start();
        return test::waitUntil([&] { return view.runs().size() >= runs && !view.isRunning(); },
                               kRunWaitMs);
    }
};

TEST(WorkbenchView, AStepIsAskedForRunsAndKeepsARunWithItsResults)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 1000));
    test::ActuatorAnswer answer;
    ASSERT_TRUE(b.view.selectTarget(b.rig->module().address, QStringLiteral("A1.01")));
    b.view.signalForm()->setSpec(step(0.25));
    ASSERT_TRUE(b.view.signalForm()->spec());
    EXPECT_EQ(b.view.signalForm()->spec()->direction, model::StepDirection::Both);
    EXPECT_EQ(b.view.signalForm()->spec()->hold, 0.25);
    ASSERT_TRUE(b.runOnce(1)) << b.view.statusText().toStdString();
    ASSERT_EQ(answer.asked.size(), 1);
    EXPECT_TRUE(answer.asked.front().join(' ').contains(QStringLiteral("A1.01")));
    const model::TuningRun &run = *b.view.runs().front();
    EXPECT_EQ(run.end, model::TestEnd::Finished);
    EXPECT_TRUE(run.restored);
    EXPECT_EQ(run.recording.setValue.y.size(), 3u); // 3 → 5 → 3
    EXPECT_EQ(run.analysis.steps.size(), 2u);
    EXPECT_EQ(b.view.resultsTable()->rowCount(), 2);
    EXPECT_TRUE(b.view.statusText().contains(QStringLiteral("A1.01")))
        << b.view.statusText().toStdString();
    EXPECT_DOUBLE_EQ(b.rig->read("A1.01").value_or(NAN), 1000);
}

TEST(WorkbenchView, NothingIsWrittenWhenThePersonSaysNo)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 700));
    test::ActuatorAnswer answer(false);
    b.view.signalForm()->setSpec(step(0.1));
    b.view.start();
    test::spinFor(100);
    EXPECT_EQ(answer.asked.size(), 1);
    EXPECT_FALSE(b.view.isRunning());
    EXPECT_TRUE(b.view.runs().empty());
    EXPECT_DOUBLE_EQ(b.rig->read("A1.01").value_or(NAN), 700);
}

TEST(WorkbenchView, TheSourceIsSwitchedOnlyAfterASecondQuestionAndPutBack)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 0));
    test::ActuatorAnswer answer;
    b.view.signalForm()->setSpec(step(0.1));
    ASSERT_TRUE(b.runOnce(1)) << b.view.statusText().toStdString();
    ASSERT_EQ(answer.asked.size(), 2);
    EXPECT_TRUE(answer.asked[1].join(' ').contains(QStringLiteral("E17")));
    EXPECT_TRUE(b.view.runs().front()->restored);
    EXPECT_DOUBLE_EQ(b.rig->read("E17").value_or(NAN), 0);
}

TEST(WorkbenchView, StopEndsTheTestAndRestores)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    ASSERT_TRUE(b.write("A1.01", 250));
    test::ActuatorAnswer answer;
    b.view.signalForm()->setSpec(step(10));
    b.view.start();
    ASSERT_TRUE(test::waitUntil([&] { return b.view.isRunning(); }));
    test::spinFor(100);
    b.view.stop();
    ASSERT_TRUE(test::waitUntil([&] { return !b.view.runs().empty(); }, kRunWaitMs));
    EXPECT_EQ(b.view.runs().front()->end, model::TestEnd::Stopped);
    EXPECT_TRUE(b.view.runs().front()->restored);
    EXPECT_DOUBLE_EQ(b.rig->read("A1.01").value_or(NAN), 250);
}

TEST(WorkbenchView, ARunSavedAndLoadedComesBackWithItsRecordingAndSettingDifferences)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.write("E17", 2));
    test::ActuatorAnswer answer;
    b.view.signalForm()->setSpec(step(0.1));
    ASSERT_TRUE(b.runOnce(1));
    model::TuningRun first = *b.view.runs().front();
    first.settings.push_back({"C1.13", 100});
    QTemporaryDir dir;
    ASSERT_EQ(model::saveRun(first, dir.filePath(QStringLiteral("run-1.csv"))), QString());
    QString why;
    auto loaded =
        model::loadRun(dir.filePath(QStringLiteral("run-1.json")), test::dictionaries(), &why);
    ASSERT_TRUE(loaded) << why.toStdString();
    EXPECT_EQ(loaded->recording.setValue.y, first.recording.setValue.y);
    ASSERT_EQ(loaded->recording.channels.size(), first.recording.channels.size());
    EXPECT_EQ(loaded->recording.channels[0].t.size(), first.recording.channels[0].t.size());
    EXPECT_EQ(loaded->analysis.steps.size(), first.analysis.steps.size());
    model::TuningRun second = *loaded;
    second.settings.back().raw = 250;
    const auto diffs = model::settingDifferences(first, second);
    ASSERT_EQ(diffs.size(), 1u);
    EXPECT_EQ(diffs[0].name, "C1.13");
    EXPECT_EQ(diffs[0].a, 100);
    EXPECT_EQ(diffs[0].b, 250);
}

} // namespace
} // namespace vt::ui
