// The reference fingerprint on the built-in simulator's position loop (tests/support/loop_bench.h,
// C1.13 = 2.00): a reference taken, saved and read back; the same module compared unchanged stays
// within every threshold; after the P gain is changed the comparison lists C1.13 and the rise time
// drifts beyond its threshold; a reference of another family or mode is refused with the reason.
#include "loop_bench.h"
#include "model/tuning/reference_session.h"

#include <QTemporaryDir>
#include <cmath>

namespace vt::model {
namespace {

constexpr int kSetWaitMs = 20'000;
constexpr double kCommissionedKp = 200; // C1.13 = 2.00
constexpr double kSoftKp = 100;         // C1.13 = 1.00: slower, no overshoot

ReferencePlan plan()
{
    ReferencePlan p;
    p.centre = 4;
    p.amplitude = 1; // 3 V ↔ 5 V as the workbench's tests step
    p.hold = 0.6;
    return p;
}

struct Taken
{
    std::vector<std::shared_ptr<TuningRun>> runs;
    std::vector<RunSetting> settings;
    std::vector<WriteItem> journal;
    QString status;
    bool complete = false;
};

Taken runSet(test::LoopBench &b, const std::vector<ReferenceTestSpec> &tests)
{
    ReferenceSetup s;
    s.module = b.rig->module();
    s.setValueRow = &b.rig->row("A1.01");
    s.tests = tests;
    EXPECT_TRUE(ReferenceSession::setupProblem(s).isEmpty())
        << ReferenceSession::setupProblem(s).toStdString();
    ReferenceSession session(b.rig->access(), s);
    Taken t;
    QObject::connect(&session, &ReferenceSession::written, &session,
                     [&](int, const std::vector<WriteItem> &items) {
                         t.journal.insert(t.journal.end(), items.begin(), items.end());
                     });
    bool done = false;
    QObject::connect(&session, &ReferenceSession::finished, &session, [&] { done = true; });
    session.start();
    EXPECT_TRUE(test::waitUntil([&] { return done; }, kSetWaitMs));
    t.runs = session.runs();
    t.settings = session.settings();
    t.status = session.statusText();
    t.complete = session.complete();
    return t;
}

const MetricDrift *find(const ReferenceComparison &c, const std::string &test, DriftMetric m)
{
    for (const MetricDrift &d : c.metrics)
        if (d.test == test && d.metric == m)
            return &d;
    return nullptr;
}

TEST(ReferenceOnTheSimulator, AChangedGainShowsAsAParameterDifferenceAndARiseTimeDrift)
{
    test::LoopBench b;
    ASSERT_TRUE(b.positionLoop(kCommissionedKp, 0));
    const ReferencePlan p = plan();
    Taken taken = runSet(b, referenceTests(p));
    ASSERT_TRUE(taken.complete) << taken.status.toStdString();
    ASSERT_EQ(taken.runs.size(), 1u);
    EXPECT_EQ(taken.runs.front()->analysis.steps.size(), 2u);
    EXPECT_FALSE(taken.journal.empty()); // the set value's restore went to the journal
    EXPECT_DOUBLE_EQ(b.read("A1.01"), 3000);
    // Every setting the module has was read, not only those written before.
    EXPECT_GT(taken.settings.size(), 20u);

    const Reference made = makeReference(b.rig->module(), b.rig->row("A1.01"), p, taken.settings,
                                         taken.runs, dev::Language::English);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("axis.vtref"));
    ASSERT_TRUE(saveReference(made, path).isEmpty());
    QString why;
    const auto reference = loadReference(path, test::dictionaries(), &why);
    ASSERT_TRUE(reference) << why.toStdString();
    EXPECT_TRUE(referenceFitProblem(reference->file, b.rig->module()).isEmpty());
    EXPECT_EQ(reference->file.version, b.rig->module().identification.version);
    ASSERT_EQ(reference->runs.size(), 1u);
    EXPECT_FALSE(reference->file.figures.empty());

    ASSERT_TRUE(b.write("C1.13", kSoftKp));
    Taken now = runSet(b, reference->tests());
    ASSERT_TRUE(now.complete) << now.status.toStdString();
    const ReferenceComparison c =
        compareWithReference(*reference, now.runs, now.settings, {}, dev::Language::English);
    ASSERT_EQ(c.params.size(), 1u);
    EXPECT_EQ(c.params.front().row, "C1.13");
    EXPECT_DOUBLE_EQ(*c.params.front().reference, 2.0);
    EXPECT_DOUBLE_EQ(*c.params.front().now, 1.0);
    const MetricDrift *rise = find(c, "step-up", DriftMetric::RiseTime);
    ASSERT_TRUE(rise);
    EXPECT_GT(rise->deltaPercent, 20); // the softer gain rises more slowly
    EXPECT_TRUE(rise->exceeded);
    EXPECT_TRUE(c.exceeded());
    ASSERT_EQ(c.overlays.size(), 2u);
    EXPECT_EQ(c.overlays.front().test, "step-up");
    EXPECT_FALSE(c.overlays.front().x.empty());
}

TEST(ReferenceOnTheSimulator, AnUnchangedModuleComparesWithinEveryThreshold)
{
    test::LoopBench b;
    ASSERT_TRUE(b.positionLoop(kCommissionedKp, 0));
    const ReferencePlan p = plan();
    Taken taken = runSet(b, referenceTests(p));
    ASSERT_TRUE(taken.complete) << taken.status.toStdString();
    const Reference reference = makeReference(b.rig->module(), b.rig->row("A1.01"), p,
                                              taken.settings, taken.runs, dev::Language::English);
    Taken now = runSet(b, reference.tests());
    ASSERT_TRUE(now.complete) << now.status.toStdString();
    const ReferenceComparison c =
        compareWithReference(reference, now.runs, now.settings, {}, dev::Language::English);
    EXPECT_TRUE(c.params.empty());
    EXPECT_EQ(c.metrics.size(), 8u); // four figures of each step
    for (const MetricDrift &d : c.metrics) {
        EXPECT_TRUE(std::isfinite(d.reference) && std::isfinite(d.now)) << d.test << " " << d.label;
        EXPECT_FALSE(d.exceeded) << d.test << " " << d.label << " " << d.reference << " → "
                                 << d.now;
    }
}

TEST(ReferenceOnTheSimulator, AReferenceOfAnotherFamilyOrModeIsRefusedWithTheReason)
{
    auto rig = test::connectSim({"dma-pn-v51", 1, {}, {}, {}});
    ASSERT_TRUE(rig);
    const ModuleInfo &module = rig->module();
    ReferenceFileData file;
    file.family = "opat";
    file.mode = module.identification.mode;
    file.setValue = "A1.01";
    file.version = module.identification.version;
    file.address = module.address;
    const QString family = referenceFitProblem(file, module);
    EXPECT_TRUE(family.contains(QStringLiteral("opat")) && family.contains(QStringLiteral("dma")))
        << family.toStdString();
    file.family = module.identification.family;
    file.mode = module.identification.mode == "2" ? "3" : "2";
    const QString mode = referenceFitProblem(file, module);
    EXPECT_TRUE(mode.contains(QStringLiteral("mode"))) << mode.toStdString();
    file.mode = module.identification.mode;
    EXPECT_TRUE(referenceFitProblem(file, module).isEmpty());
    file.address = module.address + 1;
    file.version = "0.0";
    EXPECT_EQ(referenceNotes(file, module).size(), 2);
    file.setValue = "C1.13";
    EXPECT_FALSE(referenceFitProblem(file, module).isEmpty());
}

} // namespace
} // namespace vt::model
