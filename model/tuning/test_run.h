// TestRun: one workbench test on one module — drives the module's bus set value along a
// TestSignal and records what the device answers. Each cycle writes the signal's value (only when
// it changed), then reads the recorded channels together with the set value itself, so every
// write is read back within one cycle and a value the device does not hold stops the test. The
// set value channel is time-stamped when the device acknowledged the write.
// Trust rules (ARCHITECTURE.md): the signal's whole range is checked against the row's limits and
// the user's window before anything is sent; the set-value source (HCS E17 = 2, SD7 device mode)
// is checked first and only switched when the caller allows it (the person confirmed the test);
// at the end or on any abort the set value and its source are written back to what they held,
// verified, and the outcome says so.
// Owner: the caller (the workbench view, the CLI's test command); GUI thread, same as the
// DeviceAccess, which must outlive it.
#pragma once

#include "model/session/device_access.h"
#include "model/session/write_job.h"
#include "model/tuning/test_recording.h"
#include "model/tuning/test_signal.h"

#include <QObject>
#include <QTimer>
#include <memory>
#include <optional>

namespace vt::model {

constexpr double kMaxRateHz = 1000;

struct TestRunSetup
{
    ModuleInfo module;
    const dev::ParamMeta *setValueRow = nullptr;
    TestSignal signal;
    std::vector<const dev::ParamMeta *> channels; // recorded each cycle (display units)
    const dev::ParamMeta *actualRow = nullptr;    // for the window; one of channels, or null
    // Travel window: stop when the actual value leaves the signal's range by more than this
    // (same unit as the set value).
    std::optional<double> window;
    // Cycles (write + read) per second; 0: as fast as the link allows. At most kMaxRateHz.
    double rateHz = 0;
    bool switchSource = false; // write the activation rows for the test, restore them after
    // Read each cycle: while (value & faultMask) differs from faultOk the module is in error and
    // the test stops.
    const dev::ParamMeta *faultRow = nullptr;
    std::uint32_t faultMask = 0;
    std::uint32_t faultOk = 0;
    AuditOrigin origin = AuditOrigin::Workbench; // what the session log names for its writes
};

enum class TestEnd {
    Finished,       // the whole signal ran
    Stopped,        // the person stopped it
    WindowExceeded, // |actual − set value| left the window
    Refused,        // nothing was written: a range, the source, or reading failed
    DeviceError,    // the device refused a write or does not hold the value written
    LinkLost,       // the link went away or stopped answering
};
const char *key(TestEnd end);

struct TestOutcome
{
    TestEnd end = TestEnd::Finished;
    QString reason;           // for people, empty when finished
    bool needsSource = false; // Refused because an activation row differs (switchSource offered)
    std::vector<WriteItem> switchNeeded; // when needsSource: what switching would write
    bool restored = false;          // the set value (and a switched source) is back and verified
    std::vector<WriteItem> restore; // what was written back, with its verification
};

class TestRun : public QObject
{
    Q_OBJECT
public:
    TestRun(DeviceAccess &access, TestRunSetup setup, QObject *parent = nullptr);
    ~TestRun() override;

    const TestRunSetup &setup() const { return m_setup; }
    const TestRecording &recording() const { return m_recording; }
    bool isRunning() const { return m_phase != Phase::Idle && m_phase != Phase::Done; }
    // Seconds of the signal done (0 before the first acknowledgement).
    double elapsed() const;

    // A setup with the rows the dictionary names for `setValue` in the module's mode: the
    // recorded channels, the response (the actual value) and the fault row (workbench_rows.h).
    static TestRunSetup setupFor(const ModuleInfo &module, const dev::ParamMeta &setValue,
                                 const TestSignal &signal);
    // The range check of the signal against the row's limits and the window (empty: fine).
    static QString rangeProblem(const TestRunSetup &setup);

    void start();
    // Ends the test as Stopped and restores (no-op when not running).
    void stop();

signals:
    void sampled();
    void finished(const vt::model::TestOutcome &outcome);

private:
    enum class Phase { Idle, Checking, Switching, Running, Restoring, Done };

    void check();
    void begin();
    void cycle();
    void readChannels();
    void scheduleNext();
    void end(TestEnd why, const QString &reason);
    void restore();
    double now() const;
    double raw(double display) const;

    DeviceAccess &m_access;
    TestRunSetup m_setup;
    TestRecording m_recording;
    TestOutcome m_outcome;
    Phase m_phase = Phase::Idle;
    std::optional<dev::RawValue> m_original;            // the set value before the test
    std::vector<WriteItem> m_sourceChanges;             // activation rows switched for the test
    std::vector<const dev::ParamMeta *> m_unrestorable; // switched, value before unknown
    std::optional<double> m_lastRaw;                    // the set value last acknowledged
    bool m_stopRequested = false;
    bool m_finalRead = false;    // the signal is done: this read ends the test
    bool m_attempted = false;    // a set-value write was sent
    double m_lateBy = 0;         // s the signal's clock waited for late cycles
    std::size_t m_jumpsDone = 0; // jumps of the signal written
    QTimer m_next;
    std::shared_ptr<DeviceAccess::ReadHandle> m_read;
    std::unique_ptr<WriteJob> m_job;
    std::shared_ptr<bool> m_alive = std::make_shared<bool>(true);
};

} // namespace vt::model

namespace vt::dev {
template<> std::optional<model::TestEnd> fromKey<model::TestEnd>(std::string_view text);
} // namespace vt::dev

Q_DECLARE_METATYPE(vt::model::TestOutcome)
