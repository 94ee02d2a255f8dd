#include "test_run.h"

#include "core/key_lookup.h"
#include "dict/cooking.h"
#include "model/monitor/set_value_step.h"
#include "model/text_language.h"
#include "model/tuning/workbench_rows.h"

#include <QLocale>
#include <QStringList>
#include <array>
#include <cmath>

namespace vt::model {

namespace {

QString rowName(const dev::ParamMeta &row)
{
    return QString::fromStdString(row.name);
}

QString displayText(const dev::ParamMeta &row, double raw)
{
    return QString::fromStdString(dev::formatValue(row, raw, textLanguage()));
}

QString numberText(double v)
{
    return QLocale().toString(v, 'g', 6);
}

// Why switching the source failed, with the row and the device's or the application's words.
QString switchFailure(const std::vector<WriteItem> &items)
{
    for (const WriteItem &item : items)
        if (!isOnDevice(item.status))
            return TestRun::tr("Switching the set-value source %1 failed: %2")
                .arg(rowName(*item.row), writeReasonText(item, textLanguage()));
    return TestRun::tr("Switching the set-value source failed.");
}

TestEnd endFor(OutcomeStatus status)
{
    switch (status) {
    case OutcomeStatus::LinkLost:
    case OutcomeStatus::Timeout: return TestEnd::LinkLost;
    case OutcomeStatus::Cancelled: return TestEnd::Stopped;
    default: return TestEnd::DeviceError;
    }
}

} // namespace

const char *key(TestEnd end)
{
    switch (end) {
    case TestEnd::Finished: return "finished";
    case TestEnd::Stopped: return "stopped";
    case TestEnd::WindowExceeded: return "window";
    case TestEnd::Refused: return "refused";
    case TestEnd::DeviceError: return "device-error";
    case TestEnd::LinkLost: return "link-lost";
    }
    return "?";
}

TestRun::TestRun(DeviceAccess &access, TestRunSetup setup, QObject *parent)
    : QObject(parent), m_access(access), m_setup(std::move(setup))
{
    m_recording.rows = m_setup.channels;
    m_recording.channels.resize(m_setup.channels.size());
    m_next.setSingleShot(true);
    m_next.setTimerType(Qt::PreciseTimer);
    connect(&m_next, &QTimer::timeout, this, &TestRun::cycle);
}

TestRun::~TestRun()
{
    *m_alive = false;
    if (m_read)
        m_read->cancel();
    // A running restore finishes on its own: the set value must go back even when the view that
    // started the test is closed (the job deletes itself when done).
    if (m_job && m_job->isRunning()) {
        WriteJob *job = m_job.release();
        job->setParent(nullptr);
        disconnect(job, nullptr, this, nullptr);
        connect(job, &WriteJob::finished, job, &QObject::deleteLater);
    }
}

double TestRun::now() const
{
    return static_cast<double>(m_access.session().elapsedNs()) * 1e-9;
}

double TestRun::elapsed() const
{
    if (m_recording.setValue.t.empty())
        return 0;
    return now() - m_recording.sessionStart - m_lateBy;
}

double TestRun::raw(double display) const
{
    return setValueRaw(*m_setup.setValueRow, display);
}

TestRunSetup TestRun::setupFor(const ModuleInfo &module, const dev::ParamMeta &setValue,
                               const TestSignal &signal)
{
    TestRunSetup setup{module, &setValue, signal,  {}, nullptr, std::nullopt,
                       0,      false,     nullptr, 0,  0};
    const dev::Dictionary &dict = *module.dictionary;
    const std::string &mode = module.identification.mode;
    setup.channels = recordedRows(dict, mode, setValue);
    setup.actualRow = responseRow(dict, mode, setValue);
    if (const dev::FaultRow *fault = faultCheck(dict, mode)) {
        setup.faultRow = dict.find(fault->row);
        setup.faultMask = fault->mask;
        setup.faultOk = fault->ok;
    }
    return setup;
}

QString TestRun::rangeProblem(const TestRunSetup &setup)
{
    const dev::ParamMeta *row = setup.setValueRow;
    if (!row || !setup.module.dictionary)
        return tr("The module has no set value a test can drive.");
    if (!row->writable() || row->isString())
        return tr("%1 cannot be written.").arg(rowName(*row));
    for (double v : {setup.signal.minimum(), setup.signal.maximum()}) {
        if (const auto error = dev::checkWrite(*row, setValueRaw(*row, v)))
            return tr("The signal reaches %1, outside %2: %3")
                .arg(displayText(*row, setValueRaw(*row, v)), rowName(*row),
                     QString::fromStdString(error->message.in(textLanguage())));
    }
    if (setup.window && !(*setup.window > 0))
        return tr("The window must be more than 0.");
    if (setup.window && !setup.actualRow)
        return tr("A window needs an actual value to watch.");
    if (setup.window && setup.actualRow->unit != row->unit)
        return tr("The window is in %1, the unit of %2; %3 is in %4.")
            .arg(QString::fromStdString(row->unit), rowName(*row), rowName(*setup.actualRow),
                 QString::fromStdString(setup.actualRow->unit));
    return {};
}

void TestRun::start()
{
    if (m_phase != Phase::Idle)
        return;
    if (const QString problem = rangeProblem(m_setup); !problem.isEmpty()) {
        m_phase = Phase::Done;
        m_outcome.end = TestEnd::Refused;
        m_outcome.reason = problem;
        m_outcome.restored = true; // nothing was written
        emit finished(m_outcome);
        return;
    }
    check();
}

void TestRun::check()
{
    m_phase = Phase::Checking;
    const dev::Dictionary &dict = *m_setup.module.dictionary;
    const auto rules = SetValueStep::activationRules(dict, m_setup.module.identification.mode);
    // Each rule's row (for a state rule the status word), the row written to meet it when that is
    // another one and readable (the control word: its value now is what goes back after the
    // test), then the set value.
    std::vector<const dev::ParamMeta *> rows;
    std::vector<std::optional<std::size_t>> writtenAt;
    for (const dev::SetValueActivation *rule : rules)
        rows.push_back(SetValueStep::ruleRow(dict, *rule));
    for (const dev::SetValueActivation *rule : rules) {
        const dev::ParamMeta *w = SetValueStep::ruleWriteRow(dict, *rule);
        if (w != SetValueStep::ruleRow(dict, *rule) && w->readable()) {
            writtenAt.push_back(rows.size());
            rows.push_back(w);
        } else {
            writtenAt.push_back(std::nullopt);
        }
    }
    rows.push_back(m_setup.setValueRow);
    const auto alive = m_alive;
    m_read = m_access.read(
        m_setup.module.address, rows, Priority::User,
        [this, alive, rules, rows, writtenAt](const ReadResult &result) {
            if (!*alive)
                return;
            if (!result.complete() || result.values.size() != rows.size()) {
                const QString why = result.failures.empty()
                                        ? tr("cancelled")
                                        : result.failures.front().outcome.reason;
                m_phase = Phase::Done;
                m_outcome.end = TestEnd::Refused;
                m_outcome.reason = tr("Reading the set value and its source failed: %1").arg(why);
                m_outcome.restored = true;
                emit finished(m_outcome);
                return;
            }
            m_original = result.values.back().value;
            const dev::Dictionary &d = *m_setup.module.dictionary;
            for (std::size_t i = 0; i < rules.size(); ++i) {
                const double held = dev::rawNumber(result.values[i].value);
                if (rules[i]->holds(held))
                    continue;
                WriteItem item;
                item.row = SetValueStep::ruleWriteRow(d, *rules[i]);
                item.value = rules[i]->value;
                if (!writtenAt[i] && item.row == rows[i])
                    item.before = result.values[i].value;
                else if (writtenAt[i])
                    item.before = result.values[*writtenAt[i]].value;
                if (!m_setup.switchSource && !m_outcome.needsSource)
                    m_outcome.reason = SetValueStep::refusalText(*m_setup.setValueRow, *rows[i],
                                                                 *rules[i], held, textLanguage());
                m_outcome.needsSource = true;
                m_sourceChanges.push_back(item);
            }
            if (!m_setup.switchSource && m_outcome.needsSource) {
                m_phase = Phase::Done;
                m_outcome.end = TestEnd::Refused;
                m_outcome.switchNeeded = std::move(m_sourceChanges);
                m_sourceChanges.clear();
                m_outcome.restored = true;
                emit finished(m_outcome);
                return;
            }
            m_outcome.needsSource = false;
            if (m_sourceChanges.empty()) {
                begin();
                return;
            }
            m_phase = Phase::Switching;
            WriteOptions options;
            options.skipUnchanged = false; // a state rule's control word may read as commanded
            m_job = std::make_unique<WriteJob>(m_access, m_setup.module.address,
                                               *m_setup.module.dictionary, m_sourceChanges,
                                               m_setup.origin, options);
            connect(m_job.get(), &WriteJob::finished, this, [this](bool complete) {
                m_sourceChanges = m_job->items();
                m_job.release()->deleteLater();
                if (!complete || m_stopRequested) {
                    end(complete ? TestEnd::Stopped : TestEnd::DeviceError,
                        complete ? QString() : switchFailure(m_sourceChanges));
                    return;
                }
                begin();
            });
            m_job->start();
        });
}

void TestRun::begin()
{
    m_phase = Phase::Running;
    if (m_stopRequested) {
        end(TestEnd::Stopped, {});
        return;
    }
    cycle();
}

void TestRun::cycle()
{
    if (m_phase != Phase::Running)
        return;
    if (m_stopRequested) {
        end(TestEnd::Stopped, {});
        return;
    }
    const bool first = m_recording.setValue.t.empty();
    double t = first ? 0 : now() - m_recording.sessionStart - m_lateBy;
    // A cycle that comes late (a loaded machine, a slow link) never skips a level of a step or
    // square: the signal's clock waits, so every level is written and held for its full time.
    const std::vector<double> &jumps = m_setup.signal.jumps();
    if (m_jumpsDone < jumps.size() &&
        t >=
            (m_jumpsDone + 1 < jumps.size() ? jumps[m_jumpsDone + 1] : m_setup.signal.duration())) {
        m_lateBy += t - jumps[m_jumpsDone];
        t = jumps[m_jumpsDone];
    }
    while (m_jumpsDone < jumps.size() && t >= jumps[m_jumpsDone])
        ++m_jumpsDone;
    if (!first && t >= m_setup.signal.duration()) {
        // One more read after the end, so the recording covers the signal's last cycle whole.
        m_finalRead = true;
        readChannels();
        return;
    }
    const double value = raw(m_setup.signal.valueAt(t));
    if (m_lastRaw && *m_lastRaw == value) {
        readChannels();
        return;
    }
    const auto alive = m_alive;
    m_attempted = true;
    m_access.write(
        m_setup.module.address, *m_setup.setValueRow, dev::RawValue{value}, Priority::User,
        m_setup.origin, [this, alive, value](const Outcome &outcome) {
            if (!*alive || m_phase != Phase::Running)
                return;
            if (outcome.status != OutcomeStatus::Ok) {
                end(endFor(outcome.status),
                    tr("Writing %1 failed: %2").arg(rowName(*m_setup.setValueRow), outcome.reason));
                return;
            }
            const double at = now();
            if (m_recording.setValue.t.empty())
                m_recording.sessionStart = at;
            m_recording.setValue.t.push_back(at - m_recording.sessionStart);
            m_recording.setValue.y.push_back(dev::toDisplay(*m_setup.setValueRow, value));
            m_lastRaw = value;
            ++m_recording.writes;
            readChannels();
        });
}

void TestRun::readChannels()
{
    // The channels, the fault row and the set value itself, in one read.
    std::vector<const dev::ParamMeta *> rows = m_setup.channels;
    if (m_setup.faultRow)
        rows.push_back(m_setup.faultRow);
    rows.push_back(m_setup.setValueRow);
    const auto alive = m_alive;
    m_read = m_access.read(
        m_setup.module.address, rows, Priority::User,
        [this, alive, rows](const ReadResult &result) {
            if (!*alive || m_phase != Phase::Running)
                return;
            if (!result.complete() || result.values.size() != rows.size()) {
                if (result.cancelled) {
                    end(TestEnd::Stopped, {});
                    return;
                }
                const Outcome &o = result.failures.front().outcome;
                end(endFor(o.status), tr("Reading the recorded values failed: %1").arg(o.reason));
                return;
            }
            const double t = now() - m_recording.sessionStart;
            ++m_recording.cycles;
            std::optional<double> actual;
            const std::size_t channels = m_setup.channels.size();
            for (std::size_t i = 0; i < channels; ++i) {
                const double v = dev::toDisplay(*rows[i], dev::rawNumber(result.values[i].value));
                m_recording.channels[i].t.push_back(t);
                m_recording.channels[i].y.push_back(v);
                if (rows[i] == m_setup.actualRow)
                    actual = v;
            }
            emit sampled();
            if (m_setup.faultRow) {
                const double fault = dev::rawNumber(result.values[channels].value);
                const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(fault));
                if ((bits & m_setup.faultMask) != m_setup.faultOk) {
                    end(TestEnd::DeviceError, tr("The module reports an error: %1 = %2.")
                                                  .arg(rowName(*m_setup.faultRow),
                                                       displayText(*m_setup.faultRow, fault)));
                    return;
                }
            }
            const double held = dev::rawNumber(result.values.back().value);
            if (m_lastRaw && held != *m_lastRaw) {
                end(TestEnd::DeviceError,
                    tr("%1 holds %2, not the %3 written: something else writes the set value.")
                        .arg(rowName(*m_setup.setValueRow), displayText(*m_setup.setValueRow, held),
                             displayText(*m_setup.setValueRow, *m_lastRaw)));
                return;
            }
            if (m_setup.window && actual) {
                const double low = m_setup.signal.minimum() - *m_setup.window;
                const double high = m_setup.signal.maximum() + *m_setup.window;
                if (*actual < low || *actual > high) {
                    end(TestEnd::WindowExceeded,
                        tr("%1 = %2 left the travel window %3 … %4.")
                            .arg(rowName(*m_setup.actualRow), numberText(*actual), numberText(low),
                                 numberText(high)));
                    return;
                }
            }
            if (m_finalRead) {
                end(TestEnd::Finished, {});
                return;
            }
            scheduleNext();
        });
}

void TestRun::scheduleNext()
{
    // Cycles start on a fixed grid from t = 0, so a slow exchange does not shift the rest. "As
    // fast as the link allows" is capped at kMaxRateHz: an in-process simulator answers at once,
    // and its plant moves in 0.5 ms steps.
    const double period =
        1.0 / (m_setup.rateHz > 0 ? std::min(m_setup.rateHz, kMaxRateHz) : kMaxRateHz);
    const double t = now() - m_recording.sessionStart - m_lateBy;
    const double due = std::ceil(t / period + 1e-9) * period;
    m_next.start(static_cast<int>(std::ceil((due - t) * 1000.0)));
}

void TestRun::stop()
{
    if (!isRunning())
        return;
    m_stopRequested = true;
    if (m_phase == Phase::Running) {
        if (m_next.isActive()) {
            m_next.stop();
            end(TestEnd::Stopped, {});
        }
        // Otherwise the exchange on the wire ends and cycle()/readChannels() see the request.
    } else if (m_phase == Phase::Checking) {
        if (m_read)
            m_read->cancel();
    }
}

void TestRun::end(TestEnd why, const QString &reason)
{
    if (m_phase == Phase::Restoring || m_phase == Phase::Done)
        return;
    m_next.stop();
    m_outcome.end = why;
    m_outcome.reason = reason;
    restore();
}

void TestRun::restore()
{
    m_phase = Phase::Restoring;
    std::vector<WriteItem> items;
    // A write that was sent but never acknowledged may still have arrived: put it back too.
    if (m_original && m_attempted) {
        WriteItem item;
        item.row = m_setup.setValueRow;
        item.value = *m_original;
        if (m_lastRaw)
            item.before = dev::RawValue{*m_lastRaw};
        items.push_back(item);
    }
    // The source goes back after the set value, so the valve never sees the test's value from
    // an analogue input again.
    // In the reverse order of switching: a state goes back before the rows that may change only
    // outside it (SD7 db_Local / db_DeviceMode only in INIT or DISABLED, HART-7 manual §4.2.1).
    for (auto it = m_sourceChanges.rbegin(); it != m_sourceChanges.rend(); ++it) {
        const WriteItem &changed = *it;
        if (!isOnDevice(changed.status))
            continue;
        if (!changed.before) {
            m_unrestorable.push_back(changed.row);
            continue;
        }
        WriteItem item;
        item.row = changed.row;
        item.value = *changed.before;
        item.before = changed.value;
        items.push_back(item);
    }
    if (!m_unrestorable.empty()) {
        QStringList names;
        for (const dev::ParamMeta *row : m_unrestorable)
            names << rowName(*row);
        m_outcome.reason += (m_outcome.reason.isEmpty() ? QString() : QStringLiteral(" "));
        m_outcome.reason += tr("%1 cannot be put back: its value before the test could not be "
                               "read.")
                                .arg(names.join(QStringLiteral(", ")));
    }
    if (items.empty()) {
        m_phase = Phase::Done;
        m_outcome.restored = m_unrestorable.empty();
        emit finished(m_outcome);
        return;
    }
    WriteOptions options;
    options.skipUnchanged = false; // the device's value is what the test left, whatever we know
    m_job = std::make_unique<WriteJob>(m_access, m_setup.module.address, *m_setup.module.dictionary,
                                       std::move(items), m_setup.origin, options);
    connect(m_job.get(), &WriteJob::finished, this, [this](bool complete) {
        m_outcome.restore = m_job->items();
        m_outcome.restored = complete && m_unrestorable.empty();
        m_job.release()->deleteLater();
        m_phase = Phase::Done;
        emit finished(m_outcome);
    });
    m_job->start();
}

} // namespace vt::model

namespace vt::dev {

template<> std::optional<model::TestEnd> fromKey<model::TestEnd>(std::string_view text)
{
    using model::TestEnd;
    constexpr std::array kEnds{TestEnd::Finished, TestEnd::Stopped,     TestEnd::WindowExceeded,
                               TestEnd::Refused,  TestEnd::DeviceError, TestEnd::LinkLost};
    return keyLookup<TestEnd>(kEnds, text);
}

} // namespace vt::dev
