// The workbench's "Guided tuning" tab (widgets/tuning/guided_panel.h) as a person uses it on the
// simulator's position loop: asked once for the steps and for each gain change, the iterations
// listed and overlaid on the response plot, Keep leaves the chosen gain, a refused change writes
// nothing and Abort puts the original gains back.
#include "actuator_answer.h"
#include "loop_bench.h"
#include "sim_rig.h"
#include "widgets/tuning/guided_panel.h"
#include "widgets/tuning/run_list.h"
#include "widgets/tuning/signal_form.h"
#include "widgets/tuning/workbench_view.h"

#include <QSignalSpy>
#include <QTableWidget>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

constexpr int kGuidedWaitMs = 20'000;

struct Bench
{
    test::LoopBench loop;
    std::unique_ptr<test::SimRig> &rig = loop.rig;
    WorkbenchView view;
    std::vector<model::WriteItem> journal;

    Bench()
    {
        view.resize(1200, 600);
        view.setConnection(&rig->access(), rig->modules);
        QObject::connect(&view, &WorkbenchView::written, &view,
                         [this](int, const std::vector<model::WriteItem> &items) {
                             journal.insert(journal.end(), items.begin(), items.end());
                         });
    }
    bool write(const char *name, double raw) { return loop.write(name, raw); }
    bool positionLoop(double kp) { return loop.positionLoop(kp, 0); }
    void prepare(double targetPct)
    {
        view.signalForm()->setSpec(test::LoopBench::upStep(0.7));
        view.guidedPanel()->setTarget({model::GainTarget::Kind::MaxOvershoot, targetPct});
        view.guidedPanel()->setMaxIterations(4);
    }
    bool waitFor(model::GuidedState state)
    {
        const auto t = [&] { return view.guidedPanel()->tuning(); };
        test::waitUntil(
            [&] {
                const auto *g = t();
                return g && (g->state() == state || g->state() == model::GuidedState::Done);
            },
            kGuidedWaitMs);
        return t() && t()->state() == state;
    }
};

TEST(GuidedPanel, ReachesTheTargetListsTheIterationsOverlaysThemAndKeepsTheGain)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.positionLoop(125));
    ASSERT_TRUE(b.view.selectTarget(b.rig->module().address, QStringLiteral("A1.01")));
    b.prepare(5);
    test::ActuatorAnswer answer;
    b.view.guidedPanel()->start();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Proposed))
        << b.view.guidedPanel()->statusText().toStdString();
    const auto *g = b.view.guidedPanel()->tuning();
    ASSERT_TRUE(g->best());
    // Asked for the steps, then for each gain change.
    ASSERT_GE(answer.asked.size(), 2);
    EXPECT_TRUE(answer.asked.front().join(' ').contains(QStringLiteral("A1.01")));
    EXPECT_TRUE(answer.asked[1].join(' ').contains(QStringLiteral("C1.13")));
    const int iterations = static_cast<int>(g->iterations().size());
    EXPECT_EQ(b.view.guidedPanel()->iterationsTable()->rowCount(), iterations);
    EXPECT_EQ(static_cast<int>(b.view.runs().size()), iterations);
    EXPECT_EQ(static_cast<int>(b.view.runList()->shownRuns().size()), iterations); // all overlaid
    const double kept = g->best()->p;
    b.view.guidedPanel()->keep();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Done));
    EXPECT_EQ(g->end(), model::GuidedEnd::Kept);
    EXPECT_DOUBLE_EQ(b.rig->read("C1.13").value_or(NAN), kept);
    bool journalled = false;
    for (const model::WriteItem &w : b.journal)
        journalled |= w.row->name == "C1.13" && dev::rawNumber(w.value) == kept &&
                      w.status == model::WriteStatus::Verified;
    EXPECT_TRUE(journalled);
}

TEST(GuidedPanel, ARefusedChangeWritesNothingAndAbortLeavesTheOriginals)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.positionLoop(125));
    b.prepare(5);
    test::ActuatorAnswer answer;
    answer.answer = true; // the steps
    QObject::connect(b.view.guidedPanel(), &GuidedPanel::activeChanged, b.view.guidedPanel(),
                     [&] { answer.answer = false; }); // every gain change after them
    b.view.guidedPanel()->start();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Proposed))
        << b.view.guidedPanel()->statusText().toStdString();
    EXPECT_EQ(answer.asked.size(), 2);
    for (const model::WriteItem &w : b.journal)
        EXPECT_NE(w.row->name, "C1.13");
    b.view.guidedPanel()->abort();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Done));
    EXPECT_EQ(b.view.guidedPanel()->tuning()->end(), model::GuidedEnd::Aborted);
    EXPECT_DOUBLE_EQ(b.rig->read("C1.13").value_or(NAN), 125);
}

TEST(GuidedPanel, TheSourceIsSwitchedOnlyAfterASecondQuestionAndPutBackAfterEachStep)
{
    Bench b;
    ASSERT_TRUE(b.rig);
    ASSERT_TRUE(b.positionLoop(125));
    ASSERT_TRUE(b.write("E17", 0));
    b.prepare(5);
    test::ActuatorAnswer answer;
    b.view.guidedPanel()->start();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Proposed))
        << b.view.guidedPanel()->statusText().toStdString();
    ASSERT_GE(answer.asked.size(), 3); // the steps, the source, the first gain change
    EXPECT_TRUE(answer.asked[1].join(' ').contains(QStringLiteral("E17")));
    EXPECT_TRUE(b.view.guidedPanel()->tuning()->setup().switchSource);
    EXPECT_DOUBLE_EQ(b.rig->read("E17").value_or(NAN), 0);
    b.view.guidedPanel()->abort();
    ASSERT_TRUE(b.waitFor(model::GuidedState::Done));
    EXPECT_DOUBLE_EQ(b.rig->read("C1.13").value_or(NAN), 125);
}

} // namespace
} // namespace vt::ui
