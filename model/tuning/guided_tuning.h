// GuidedTuning: the guided gain change of the tuning workbench (issue #18 §3) on one module's
// loop — measure a step, propose the next P gain (GainSearch), write it once the person agreed,
// measure again — until the target is met, the iterations run out or the person ends it.
// Trust rules (ARCHITECTURE.md): the gains are read first and kept as the originals; every gain
// write is confirmed (the `confirm` callback the GUI answers, or an "allow the next N" allowance),
// range-checked, written one row at a time and read back (WriteJob). Keep writes the best gains
// found (when the device does not already hold them); Abort, a failed test, a fault or a lost
// link writes the originals back, verified. No gains of an intermediate iteration stay behind.
// Each iteration is a TuningRun (the workbench overlays them); every write is handed to the
// journal (`written`). The step tests themselves are confirmed once, before start().
// Owner: the workbench's guided-tuning panel, the tests; GUI thread, same as the DeviceAccess,
// which must outlive it.
#pragma once

#include "model/tuning/gain_search.h"
#include "model/tuning/test_run.h"
#include "model/tuning/tuning_run.h"

#include <QObject>
#include <QStringList>
#include <functional>
#include <memory>

namespace vt::model {

// The loop gains of the set value's branch: C1.13 / C1.17 for A1.01, C2.13 / C2.17 for A2.01.
struct GainRows
{
    const dev::ParamMeta *p = nullptr;
    const dev::ParamMeta *i = nullptr; // null when the dictionary has none
};
// Empty `p` when the dictionary has no P gain for that branch.
GainRows gainRows(const dev::Dictionary &dictionary, const dev::ParamMeta &setValue);

struct GuidedSetup
{
    ModuleInfo module;
    const dev::ParamMeta *setValueRow = nullptr;
    GainRows gains;
    std::vector<const dev::ParamMeta *> channels;
    const dev::ParamMeta *actualRow = nullptr; // the response the overshoot is read from
    SignalSpec step;                           // an up step (from → to, hold)
    double rateHz = 0;
    std::optional<double> window;
    bool switchSource = false;
    GainTarget target;
    int maxIterations = 6;
    AuditOrigin origin = AuditOrigin::Workbench; // what the session log names for its writes
};

enum class GuidedState {
    Idle,
    Reading,   // the original gains
    Testing,   // a step test runs
    Asking,    // waiting for the person to agree to a gain write
    Writing,   // a gain write
    Proposed,  // the search is over: Keep or Abort
    Restoring, // writing the originals back
    Done,
};

enum class GuidedEnd { Kept, Aborted, Failed };

struct GuidedIteration
{
    Gains gains;
    std::shared_ptr<TuningRun> run;
    std::optional<StepMetrics> metrics; // the up step's
    std::optional<StepProblem> problem; // why it has none
};

class GuidedTuning : public QObject
{
    Q_OBJECT
public:
    // `lines` describe the write; `answer(true)` to write.
    using Confirm = std::function<void(const QStringList &lines, std::function<void(bool)> answer)>;

    GuidedTuning(DeviceAccess &access, GuidedSetup setup, Confirm confirm,
                 QObject *parent = nullptr);
    ~GuidedTuning() override;

    // Checks the setup (empty: fine; else why, for people): rows, the step, the target.
    static QString setupProblem(const GuidedSetup &setup);

    const GuidedSetup &setup() const { return m_setup; }
    GuidedState state() const { return m_state; }
    bool isActive() const { return m_state != GuidedState::Idle && m_state != GuidedState::Done; }
    // The next `n` gain writes go without asking (each one used counts down).
    void allowNext(int n) { m_allowance = std::max(0, n); }
    int allowance() const { return m_allowance; }
    const std::optional<Gains> &original() const { return m_original; }
    const std::optional<Gains> &best() const { return m_best; }
    const std::optional<Gains> &onDevice() const { return m_current; }
    const std::vector<GuidedIteration> &iterations() const { return m_iterations; }
    const TestRun *test() const { return m_test.get(); }
    // The last thing said (for people): the proposal, why it stopped, what was restored.
    QString statusText() const { return m_status; }
    GuidedEnd end() const { return m_end; }
    // The last run needed the set-value source switched (start again with switchSource).
    bool needsSource() const { return m_needsSource; }

    void start();
    // Proposed only: keeps the best gains on the device (writing them when needed).
    void keep();
    // Any time while active: stops a running test and writes the originals back.
    void abort();

signals:
    void iterationDone(int index);
    void stateChanged();
    // Every write of the guided change (the gains, their restore) and the test's set-value
    // restores: for the monitor's journal.
    void written(int module, const std::vector<vt::model::WriteItem> &items);
    void finished(vt::model::GuidedEnd end, const QString &text);

private:
    void setState(GuidedState state);
    void readOriginals();
    void runTest();
    void onTest(const TestOutcome &outcome);
    void propose(const GainProposal &proposal);
    void askToWrite(const Gains &gains, const QString &why, std::function<void()> then);
    void writeGains(const Gains &gains, std::function<void(bool)> then);
    void restore(const QString &why);
    void finish(GuidedEnd end, const QString &text);
    QString gainsText(const Gains &gains) const;

    DeviceAccess &m_access;
    GuidedSetup m_setup;
    Confirm m_confirm;
    GuidedState m_state = GuidedState::Idle;
    GuidedEnd m_end = GuidedEnd::Aborted;
    std::optional<GainSearch> m_search;
    std::optional<Gains> m_original;
    std::optional<Gains> m_current; // on the device (verified), when known
    std::optional<Gains> m_best;
    int m_allowance = 0;
    bool m_abortRequested = false;
    bool m_needsSource = false;
    QString m_status;
    std::vector<GuidedIteration> m_iterations;
    std::unique_ptr<TestRun> m_test;
    std::unique_ptr<TuningRun> m_live;
    std::unique_ptr<WriteJob> m_job;
    std::shared_ptr<DeviceAccess::ReadHandle> m_read;
    std::shared_ptr<bool> m_alive = std::make_shared<bool>(true);
};

} // namespace vt::model
