// ReferenceSession: runs a reference fingerprint's test set (reference_fingerprint.h) on one
// module — reads every setting of the module first (so the snapshot is the device's, not what the
// image happened to hold), then runs each test through the workbench's engine (TestRun) in turn
// and keeps each as an analysed run. Used to take a reference and to repeat its tests for a
// comparison.
// Trust rules (ARCHITECTURE.md): the caller asks the person once for the whole set before start();
// each test checks its range and the set-value source, writes the set value back (and a switched
// source) when it ends, verified, as every workbench test does; the first test that does not run
// to its end ends the set. Every restore is handed to the journal (`written`).
// Owner: the workbench's reference panel, the tests; GUI thread, same as the DeviceAccess, which
// must outlive it.
#pragma once

#include "model/tuning/reference_fingerprint.h"
#include "model/tuning/test_run.h"

#include <QObject>
#include <memory>

namespace vt::model {

struct ReferenceSetup
{
    ModuleInfo module;
    const dev::ParamMeta *setValueRow = nullptr;
    std::vector<ReferenceTestSpec> tests;
    double rateHz = 0;
    std::optional<double> window;
    bool switchSource = false;
};

class ReferenceSession : public QObject
{
    Q_OBJECT
public:
    ReferenceSession(DeviceAccess &access, ReferenceSetup setup, QObject *parent = nullptr);
    ~ReferenceSession() override;

    // Why the set cannot run (empty: fine): rows, each test's signal and range.
    static QString setupProblem(const ReferenceSetup &setup);
    // The whole set's duration in seconds and the range it drives the set value through.
    static double duration(const ReferenceSetup &setup);

    const ReferenceSetup &setup() const { return m_setup; }
    bool isActive() const { return m_active; }
    // Tests done so far, in the setup's order; after a complete set one per test.
    const std::vector<std::shared_ptr<TuningRun>> &runs() const { return m_runs; }
    // The settings as read before the first test (those that could not be read are missing).
    const std::vector<RunSetting> &settings() const { return m_settings; }
    bool complete() const { return m_complete; }
    // A test was refused because the set-value source differs; what switching would write.
    bool needsSource() const { return m_outcome.needsSource; }
    const TestOutcome &lastOutcome() const { return m_outcome; }
    const TestRun *test() const { return m_test.get(); }
    QString statusText() const { return m_status; }

    void start();
    // Stops the running test (it restores) and ends the set.
    void stop();

signals:
    void progress();
    void written(int module, const std::vector<vt::model::WriteItem> &items);
    // `complete`: every test ran to its end; else statusText() says why not.
    void finished(bool complete);

private:
    void readSettings();
    void runTest();
    void onTest(const TestOutcome &outcome);
    void finish(bool complete, const QString &text);

    DeviceAccess &m_access;
    ReferenceSetup m_setup;
    bool m_active = false;
    bool m_complete = false;
    bool m_stopRequested = false;
    bool m_reading = false; // the settings are being read (m_read)
    QString m_status;
    TestOutcome m_outcome;
    std::vector<RunSetting> m_settings;
    std::vector<std::shared_ptr<TuningRun>> m_runs;
    std::unique_ptr<TestRun> m_test;
    std::unique_ptr<TuningRun> m_live;
    std::shared_ptr<DeviceAccess::ReadHandle> m_read;
    std::shared_ptr<bool> m_alive = std::make_shared<bool>(true);
};

} // namespace vt::model
