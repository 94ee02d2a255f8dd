// The workbench's Reference tab (widgets/tuning/reference_panel.h) as a person uses it, on the
// built-in simulator's position loop (C1.13 = 2.00): Save as Reference asks once for the whole
// set and writes the file; after the P gain changed, Compare with Reference asks once, lists
// C1.13 and marks the rise time exceeded; a file of another mode is refused with the reason and
// nothing is asked.
#include "actuator_answer.h"
#include "loop_bench.h"
#include "widgets/tuning/reference_drift_view.h"
#include "widgets/tuning/reference_panel.h"
#include "widgets/tuning/workbench_view.h"

#include <QFile>
#include <QTableWidget>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

constexpr int kSetWaitMs = 20'000;

struct Bench
{
    test::LoopBench loop;
    WorkbenchView view;
    QTemporaryDir dir;
    QString path = dir.filePath(QStringLiteral("axis.vtref"));

    bool ready()
    {
        if (!loop.positionLoop(200, 0))
            return false;
        view.resize(1400, 700);
        view.setConnection(&loop.rig->access(), loop.rig->modules);
        if (!view.selectTarget(loop.rig->module().address, QStringLiteral("A1.01")))
            return false;
        model::ReferencePlan plan;
        plan.centre = 4;
        plan.amplitude = 1;
        plan.hold = 0.6;
        panel()->setPlan(plan);
        return true;
    }
    ReferencePanel *panel() const { return view.referencePanel(); }
    bool settled()
    {
        return test::waitUntil([&] { return !panel()->isActive(); }, kSetWaitMs);
    }
};

bool tableHas(const QTableWidget *table, const QString &text)
{
    for (int r = 0; r < table->rowCount(); ++r)
        for (int c = 0; c < table->columnCount(); ++c)
            if (table->item(r, c) && table->item(r, c)->text().contains(text))
                return true;
    return false;
}

TEST(ReferencePanel, SavesAReferenceAndShowsTheDriftOfAChangedGain)
{
    Bench b;
    ASSERT_TRUE(b.ready());
    test::ActuatorAnswer answer;
    b.panel()->saveAs(b.path);
    EXPECT_TRUE(b.panel()->isActive());
    ASSERT_TRUE(b.settled());
    ASSERT_TRUE(QFile::exists(b.path)) << b.panel()->statusText().toStdString();
    EXPECT_EQ(answer.asked.size(), 1); // once for the whole set
    EXPECT_TRUE(answer.asked.front().join(' ').contains(QStringLiteral("A1.01")));
    EXPECT_TRUE(b.panel()->statusText().contains(b.path)) << b.panel()->statusText().toStdString();
    EXPECT_GT(b.panel()->driftView()->figuresTable()->rowCount(), 0); // the reference's own

    ASSERT_TRUE(b.loop.write("C1.13", 100));
    b.panel()->compareWith(b.path);
    ASSERT_TRUE(b.settled());
    EXPECT_EQ(answer.asked.size(), 2);
    ASSERT_TRUE(b.panel()->comparison()) << b.panel()->statusText().toStdString();
    EXPECT_TRUE(b.panel()->comparison()->exceeded());
    EXPECT_TRUE(tableHas(b.panel()->driftView()->settingsTable(), QStringLiteral("C1.13")));
    EXPECT_TRUE(tableHas(b.panel()->driftView()->figuresTable(), QStringLiteral("exceeded")));
    EXPECT_DOUBLE_EQ(b.loop.read("A1.01"), 3000); // the set value is back

    // A looser threshold recomputes the verdicts without running again.
    model::DriftThresholds loose;
    loose.riseTimePct = 1000;
    loose.settlingPct = 1000;
    loose.overshootPoints = 100;
    loose.steadyStatePctOfStep = 100;
    b.panel()->setThresholds(loose);
    EXPECT_FALSE(b.panel()->comparison()->exceeded());
    EXPECT_EQ(answer.asked.size(), 2);
}

TEST(ReferencePanel, AReferenceOfAnotherModeIsRefusedWithTheReasonBeforeAnythingIsAsked)
{
    Bench b;
    ASSERT_TRUE(b.ready());
    const std::string mode = b.loop.rig->module().identification.mode;
    model::ReferenceFileData file;
    file.family = b.loop.rig->module().identification.family;
    file.mode = mode == "2" ? "3" : "2";
    file.setValue = "A1.01";
    {
        QFile out(b.path);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(QByteArray::fromStdString(model::referenceJson(file)));
    }
    test::ActuatorAnswer answer;
    b.panel()->compareWith(b.path);
    EXPECT_FALSE(b.panel()->isActive());
    EXPECT_TRUE(answer.asked.isEmpty());
    EXPECT_TRUE(b.panel()->statusText().contains(QStringLiteral("mode")))
        << b.panel()->statusText().toStdString();
}

} // namespace
} // namespace vt::ui
