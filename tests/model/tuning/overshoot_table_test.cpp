// Issue #18's simulator test: the overshoot the workbench measures (TestRun + analyseRun, over the
// bus) rises with C1.13 as docs/SIMULATOR-PLANT.md's table says ("What the tests measure":
// A1.01 3 V → 5 V, 0 … 10 V sensor, P only: C1.13 = 2.00 / 3.00 / 4.00 → 0.3 / 18 / 42 %).
#include "loop_bench.h"

namespace vt::model {
namespace {

TEST(WorkbenchOnTheSimulator, OvershootRisesWithC1_13AsThePlantTableSays)
{
    test::LoopBench b;
    ASSERT_TRUE(b.positionLoop(100, 0));
    struct Point
    {
        double kp;
        double tablePct;
        double tolerancePct;
        double hold; // s: long enough for the step to settle (the analysis refuses it else)
    };
    // The bus samples the response (not every 0.5 ms plant step), so the peak read can fall a
    // little short of the plant's own. C1.13 = 4.00 (42 %) rings for more than a second and
    // needs a 2 s hold (measured 42.5 %); left out to keep the test short.
    const std::vector<Point> table = {
        {100, 0, 0.5, 1.0}, {200, 0.3, 0.5, 0.6}, {300, 18, 1.5, 0.8}};
    std::vector<double> measured;
    for (const Point &p : table) {
        ASSERT_TRUE(b.write("C1.13", p.kp));
        TestRunSetup setup = TestRun::setupFor(b.rig->module(), b.rig->row("A1.01"),
                                               *TestSignal::make(test::LoopBench::upStep(p.hold)));
        setup.channels = b.channels();
        setup.actualRow = &b.rig->row("d1.11");
        TestRun run(b.rig->access(), setup);
        std::optional<TestOutcome> done;
        QObject::connect(&run, &TestRun::finished, &run, [&](const TestOutcome &o) { done = o; });
        run.start();
        ASSERT_TRUE(test::waitFor(done, 10'000));
        ASSERT_EQ(done->end, TestEnd::Finished) << done->reason.toStdString();
        const RunAnalysis a =
            analyseRun(setup.signal, run.recording(), setup.actualRow, setup.setValueRow);
        ASSERT_FALSE(a.steps.empty());
        ASSERT_TRUE(a.steps.front().metrics)
            << "C1.13 = " << p.kp << ": " << stepProblemKey(*a.steps.front().problem);
        const double pct = a.steps.front().metrics->overshootPct;
        EXPECT_NEAR(pct, p.tablePct, p.tolerancePct) << "C1.13 = " << p.kp;
        if (!measured.empty()) {
            EXPECT_GT(pct, measured.back()) << "C1.13 = " << p.kp;
        }
        measured.push_back(pct);
    }
}

} // namespace
} // namespace vt::model
