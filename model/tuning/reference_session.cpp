#include "reference_session.h"

#include <QTimer>

namespace vt::model {

ReferenceSession::ReferenceSession(DeviceAccess &access, ReferenceSetup setup, QObject *parent)
    : QObject(parent), m_access(access), m_setup(std::move(setup))
{
}

ReferenceSession::~ReferenceSession()
{
    *m_alive = false;
    if (m_read)
        m_read->cancel();
}

QString ReferenceSession::setupProblem(const ReferenceSetup &s)
{
    if (!s.module.dictionary || !s.setValueRow)
        return tr("Choose a module and a set value first.");
    if (s.tests.empty())
        return tr("The reference has no tests.");
    for (const ReferenceTestSpec &t : s.tests) {
        std::string why;
        const auto signal = TestSignal::make(t.spec, &why);
        if (!signal)
            return tr("The test %1 cannot be run: %2")
                .arg(QString::fromStdString(t.key), QString::fromStdString(why));
        TestRunSetup test = TestRun::setupFor(s.module, *s.setValueRow, *signal);
        test.window = s.window;
        if (const QString problem = TestRun::rangeProblem(test); !problem.isEmpty())
            return problem;
    }
    return {};
}

double ReferenceSession::duration(const ReferenceSetup &s)
{
    double total = 0;
    for (const ReferenceTestSpec &t : s.tests)
        if (const auto signal = TestSignal::make(t.spec))
            total += signal->duration();
    return total;
}

void ReferenceSession::start()
{
    if (m_active || m_complete)
        return;
    if (const QString problem = setupProblem(m_setup); !problem.isEmpty())
        return finish(false, problem);
    m_active = true;
    readSettings();
}

void ReferenceSession::readSettings()
{
    const ModuleInfo &module = m_setup.module;
    std::vector<const dev::ParamMeta *> rows;
    for (const dev::ParamMeta &row : module.dictionary->params)
        if (row.kind == dev::RowKind::Setting && !row.isString() && row.readable() &&
            row.appliesTo(module.identification.version, module.identification.mode))
            rows.push_back(&row);
    m_status = tr("Reading the settings of module %1…").arg(module.address);
    emit progress();
    const auto alive = m_alive;
    m_reading = true;
    // Rows that fail to read are left out of the snapshot: it holds what the device confirmed.
    m_read = m_access.read(module.address, std::move(rows), Priority::User,
                           [this, alive](const ReadResult &r) {
                               if (!*alive || !m_active)
                                   return;
                               m_reading = false;
                               if (m_stopRequested || r.cancelled)
                                   return finish(false, tr("Stopped before a test ran."));
                               m_settings = settingsSnapshot(m_access.image(), m_setup.module);
                               runTest();
                           });
}

void ReferenceSession::runTest()
{
    const std::size_t index = m_runs.size();
    const ReferenceTestSpec &t = m_setup.tests[index];
    const auto signal = TestSignal::make(t.spec);
    if (!signal)
        return finish(false, tr("The test %1 cannot be run.").arg(QString::fromStdString(t.key)));
    TestRunSetup test = TestRun::setupFor(m_setup.module, *m_setup.setValueRow, *signal);
    test.rateHz = m_setup.rateHz;
    test.window = m_setup.window;
    test.switchSource = m_setup.switchSource;
    m_live = newRun(static_cast<int>(index) + 1, test, m_access.image());
    m_live->settings = m_settings;
    m_test = std::make_unique<TestRun>(m_access, std::move(test));
    connect(m_test.get(), &TestRun::finished, this, &ReferenceSession::onTest);
    connect(m_test.get(), &TestRun::sampled, this, &ReferenceSession::progress);
    m_status = tr("Test %1 of %2 runs…").arg(index + 1).arg(m_setup.tests.size());
    emit progress();
    // A test before may have written back an EEPROM row (the source E17): the module takes the
    // next EEPROM write only after its pacing time (DMA Profinet manual §3.4.1).
    const auto alive = m_alive;
    QTimer::singleShot(index == 0 ? 0 : m_setup.module.dictionary->writePacingMs, this,
                       [this, alive] {
                           if (!*alive || !m_test || m_test->isRunning())
                               return;
                           if (m_stopRequested)
                               return finish(false, tr("Stopped."));
                           m_test->start();
                       });
}

void ReferenceSession::onTest(const TestOutcome &outcome)
{
    // The engine emitted this from its own code: it goes later, its recording now.
    TestRecording recording = m_test->recording();
    m_test.release()->deleteLater();
    m_outcome = outcome;
    if (!outcome.restore.empty())
        emit written(m_setup.module.address, outcome.restore);
    if (outcome.end != TestEnd::Finished)
        return finish(false, tr("Test %1 of %2 ended early: %3")
                                 .arg(m_runs.size() + 1)
                                 .arg(m_setup.tests.size())
                                 .arg(outcome.reason.isEmpty() ? tr("stopped") : outcome.reason));
    auto run = std::shared_ptr<TuningRun>(std::move(m_live));
    run->recording = std::move(recording);
    run->end = outcome.end;
    run->restored = outcome.restored;
    run->analysis = analyseRun(*TestSignal::make(run->spec), run->recording, run->responseRow,
                               run->setValueRow);
    m_runs.push_back(std::move(run));
    if (!outcome.restored)
        return finish(
            false,
            tr("The set value is NOT restored after test %1: check the valve.").arg(m_runs.size()));
    if (m_runs.size() == m_setup.tests.size())
        return finish(true,
                      tr("All %1 tests ran; the set value is restored.").arg(m_setup.tests.size()));
    if (m_stopRequested)
        return finish(false, tr("Stopped."));
    runTest();
}

void ReferenceSession::stop()
{
    if (!m_active)
        return;
    m_stopRequested = true;
    if (m_reading && m_read) {
        m_reading = false;
        m_read->cancel();
        if (m_active)
            finish(false, tr("Stopped before a test ran."));
        return;
    }
    if (m_test && m_test->isRunning())
        m_test->stop(); // onTest ends the set after the restore
}

void ReferenceSession::finish(bool complete, const QString &text)
{
    m_active = false;
    m_complete = complete;
    m_status = text;
    m_test.reset();
    m_live.reset();
    emit finished(complete);
}

} // namespace vt::model
