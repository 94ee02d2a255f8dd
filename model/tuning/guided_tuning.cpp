#include "guided_tuning.h"

#include "dict/cooking.h"
#include "model/text_language.h"

#include <QTimer>
#include <cmath>
#include <limits>

namespace vt::model {

GainRows gainRows(const dev::Dictionary &dictionary, const dev::ParamMeta &setValue)
{
    // HCS C block (DMA Profinet manual §4.4 "C-Parameter"; OPAT manual "C-Parameter"):
    // Cb.13 is the P portion KP1 and Cb.17 the I portion of branch b.
    const int branch = setValue.branch > 0 ? setValue.branch : 1;
    const std::string prefix = "C" + std::to_string(branch) + ".";
    GainRows rows;
    rows.p = dictionary.find(prefix + "13");
    if (rows.p)
        rows.i = dictionary.find(prefix + "17");
    return rows;
}

namespace {

// The response crossed the step's set value `to` during the step's hold: a step that did not
// settle because it rings, not because it creeps (a creeping one needs a longer hold).
bool rangPast(const TuningRun &run, const StepEdge &edge)
{
    const Samples *x = run.recording.channel(run.responseRow);
    if (!x)
        return false;
    const double margin = 0.02 * std::abs(edge.to - edge.from); // the settling band
    const double sign = edge.to > edge.from ? 1.0 : -1.0;
    for (std::size_t k = 0; k < x->t.size(); ++k)
        if (x->t[k] > edge.time && x->t[k] <= edge.end && sign * (x->y[k] - edge.to) > margin)
            return true;
    return false;
}

} // namespace

GuidedTuning::GuidedTuning(DeviceAccess &access, GuidedSetup setup, Confirm confirm,
                           QObject *parent)
    : QObject(parent), m_access(access), m_setup(std::move(setup)), m_confirm(std::move(confirm))
{
}

GuidedTuning::~GuidedTuning()
{
    *m_alive = false;
    if (m_read)
        m_read->cancel();
}

QString GuidedTuning::setupProblem(const GuidedSetup &s)
{
    if (!s.module.dictionary || !s.setValueRow)
        return tr("Choose a module and a set value first.");
    if (!s.gains.p)
        return tr("The dictionary names no P gain for %1: there is nothing to tune.")
            .arg(QString::fromStdString(s.setValueRow->name));
    if (!s.actualRow)
        return tr("The dictionary names no response for %1: there is no overshoot to measure.")
            .arg(QString::fromStdString(s.setValueRow->name));
    if (s.step.kind != SignalKind::Step || !(s.step.to > s.step.from) || !(s.step.hold > 0))
        return tr("The guided change measures an up step: From below To, with a hold time.");
    if (s.target.kind == GainTarget::Kind::MaxOvershoot && !(s.target.maxOvershootPct > 0))
        return tr("The overshoot limit must be more than 0 %.");
    if (s.maxIterations < 1)
        return tr("Allow at least one iteration.");
    return {};
}

void GuidedTuning::setState(GuidedState state)
{
    m_state = state;
    emit stateChanged();
}

QString GuidedTuning::gainsText(const Gains &g) const
{
    const dev::Language lang = textLanguage();
    QString text = QStringLiteral("%1 = %2").arg(
        QString::fromStdString(m_setup.gains.p->name),
        QString::fromStdString(dev::formatValue(*m_setup.gains.p, g.p, lang)));
    if (m_setup.gains.i)
        text += QStringLiteral(", %1 = %2")
                    .arg(QString::fromStdString(m_setup.gains.i->name),
                         QString::fromStdString(dev::formatValue(*m_setup.gains.i, g.i, lang)));
    return text;
}

void GuidedTuning::start()
{
    if (m_state != GuidedState::Idle)
        return;
    if (const QString problem = setupProblem(m_setup); !problem.isEmpty())
        return finish(GuidedEnd::Failed, problem);
    readOriginals();
}

void GuidedTuning::readOriginals()
{
    setState(GuidedState::Reading);
    std::vector<const dev::ParamMeta *> rows{m_setup.gains.p};
    if (m_setup.gains.i)
        rows.push_back(m_setup.gains.i);
    const auto alive = m_alive;
    m_read = m_access.read(
        m_setup.module.address, rows, Priority::User, [this, alive, rows](const ReadResult &r) {
            if (!*alive || m_state != GuidedState::Reading)
                return;
            if (!r.complete() || r.values.size() != rows.size())
                return finish(GuidedEnd::Failed,
                              tr("Reading the gains failed: %1")
                                  .arg(r.failures.empty() ? tr("cancelled")
                                                          : r.failures.front().outcome.reason));
            Gains g{dev::rawNumber(r.values[0].value),
                    rows.size() > 1 ? dev::rawNumber(r.values[1].value) : 0.0};
            m_original = g;
            m_current = g;
            const dev::Limits limits = dev::rowLimits(*m_setup.gains.p);
            m_search.emplace(m_setup.target, g, limits.min, limits.max, m_setup.maxIterations);
            if (m_abortRequested)
                return finish(GuidedEnd::Aborted, tr("Aborted before anything was written."));
            runTest();
        });
}

void GuidedTuning::runTest()
{
    const auto signal = TestSignal::make(m_setup.step);
    if (!signal || !m_current)
        return restore(tr("The step cannot be run."));
    setState(GuidedState::Testing);
    TestRunSetup test = TestRun::setupFor(m_setup.module, *m_setup.setValueRow, *signal);
    test.channels = m_setup.channels;
    test.actualRow = m_setup.actualRow;
    test.window = m_setup.window;
    test.rateHz = m_setup.rateHz;
    test.origin = m_setup.origin;
    test.switchSource = m_setup.switchSource;
    m_live = newRun(static_cast<int>(m_iterations.size()) + 1, test, m_access.image());
    m_test = std::make_unique<TestRun>(m_access, std::move(test));
    connect(m_test.get(), &TestRun::finished, this, &GuidedTuning::onTest);
    // After a gain write (EEPROM) the test may switch the source E17 (EEPROM too): the same
    // pacing as before a gain write (writeGains).
    const auto alive = m_alive;
    QTimer::singleShot(m_setup.module.dictionary->writePacingMs, this, [this, alive] {
        if (*alive && m_test && !m_test->isRunning() && m_state == GuidedState::Testing)
            m_test->start();
    });
}

void GuidedTuning::onTest(const TestOutcome &outcome)
{
    // The engine emitted this from its own code: it goes later, its recording now.
    TestRecording recording = m_test->recording();
    m_test.release()->deleteLater();
    if (!outcome.restore.empty())
        emit written(m_setup.module.address, outcome.restore);
    if (outcome.end == TestEnd::Refused && outcome.needsSource)
        m_needsSource = true;
    if (m_abortRequested)
        return restore(tr("Aborted."));
    if (outcome.end != TestEnd::Finished)
        return restore(tr("The step test ended early: %1").arg(outcome.reason));

    auto run = std::shared_ptr<TuningRun>(std::move(m_live));
    run->recording = std::move(recording);
    run->end = outcome.end;
    run->restored = outcome.restored;
    run->analysis = analyseRun(*TestSignal::make(run->spec), run->recording, run->responseRow,
                               run->setValueRow);
    const StepResult *up = nullptr; // the step's up edge
    for (const StepResult &s : run->analysis.steps)
        if (!up && s.edge.to > s.edge.from)
            up = &s;
    GuidedIteration it{*m_current, run, up ? up->metrics : std::nullopt,
                       up ? up->problem : std::nullopt};
    m_iterations.push_back(it);
    emit iterationDone(static_cast<int>(m_iterations.size()) - 1);
    if (m_abortRequested) // asked for while the iteration was shown
        return restore(tr("Aborted."));
    if (!it.metrics && up && up->problem == StepProblem::NotSettled && rangPast(*run, up->edge)) {
        m_status = tr("Iteration %1: %2 rang past the set value and did not settle within the "
                      "hold.")
                       .arg(m_iterations.size())
                       .arg(gainsText(it.gains));
        return propose(m_search->measured(it.gains, std::numeric_limits<double>::infinity()));
    }
    if (!it.metrics) {
        const QString why =
            it.problem ? QString::fromLatin1(stepProblemKey(*it.problem).data()) : tr("no step");
        if (it.problem == StepProblem::NoResponse)
            return restore(tr("The step at %1 did not move the response (%2): check the feedback "
                              "and the controller.")
                               .arg(gainsText(it.gains), why));
        return restore(tr("The step at %1 gave no figures (%2): hold it longer.")
                           .arg(gainsText(it.gains), why));
    }
    propose(m_search->measured(it.gains, it.metrics->overshootPct));
}

void GuidedTuning::propose(const GainProposal &p)
{
    const GuidedIteration &last = m_iterations.back();
    const QString measured = last.metrics
                                 ? tr("Iteration %1: %2 gave %3 % overshoot.")
                                       .arg(m_iterations.size())
                                       .arg(gainsText(last.gains),
                                            QLocale().toString(last.metrics->overshootPct, 'f', 1))
                                 : m_status;
    m_best = p.best;
    switch (p.verdict) {
    case GainVerdict::Measure:
        askToWrite(p.next, measured + QLatin1Char(' ') + tr("Next: %1.").arg(gainsText(p.next)),
                   [this, next = p.next] {
                       writeGains(next, [this](bool ok) {
                           if (m_abortRequested)
                               return restore(tr("Aborted."));
                           if (!ok)
                               return restore(tr("The gains could not be written."));
                           runTest();
                       });
                   });
        return;
    case GainVerdict::Reached:
        m_status = measured + QLatin1Char(' ') +
                   tr("Target reached with %1: Keep leaves these gains on the device, Abort "
                      "puts back %2.")
                       .arg(gainsText(*m_best), gainsText(*m_original));
        return setState(GuidedState::Proposed);
    case GainVerdict::Exhausted:
        if (!m_best)
            return restore(measured + QLatin1Char(' ') +
                           tr("No gain within the limit was found in the iterations allowed."));
        m_status = measured + QLatin1Char(' ') +
                   tr("The iterations ran out; the best within the limit is %1: Keep or Abort.")
                       .arg(gainsText(*m_best));
        return setState(GuidedState::Proposed);
    case GainVerdict::Unreachable:
        return restore(measured + QLatin1Char(' ') +
                       tr("Even the lowest gain overshoots more than the limit; the I portion or "
                          "the ramps need a look."));
    }
}

void GuidedTuning::askToWrite(const Gains &gains, const QString &why, std::function<void()> then)
{
    m_status = why;
    if (m_allowance > 0) {
        --m_allowance;
        return then();
    }
    setState(GuidedState::Asking);
    const QStringList lines = {
        why, tr("Module %1: write %2?").arg(m_setup.module.address).arg(gainsText(gains))};
    const auto alive = m_alive;
    const int asked = static_cast<int>(m_iterations.size());
    m_confirm(lines, [this, alive, asked, then](bool yes) {
        if (!*alive || m_state != GuidedState::Asking ||
            asked != static_cast<int>(m_iterations.size()))
            return;
        if (yes)
            return then();
        m_status = tr("The change was refused; nothing was written. The device holds %1.")
                       .arg(gainsText(*m_current));
        if (m_best && *m_best == *m_current)
            m_status += QLatin1Char(' ') + tr("Keep or Abort.");
        setState(GuidedState::Proposed);
    });
}

void GuidedTuning::writeGains(const Gains &gains, std::function<void(bool)> then)
{
    setState(GuidedState::Writing);
    std::vector<WriteItem> items;
    const auto item = [&](const dev::ParamMeta *row, double value, std::optional<double> before) {
        WriteItem w;
        w.row = row;
        w.value = value;
        if (before)
            w.before = *before;
        items.push_back(w);
    };
    item(m_setup.gains.p, gains.p, m_current ? std::optional<double>(m_current->p) : std::nullopt);
    if (m_setup.gains.i)
        item(m_setup.gains.i, gains.i,
             m_current ? std::optional<double>(m_current->i) : std::nullopt);
    m_job = std::make_unique<WriteJob>(m_access, m_setup.module.address, *m_setup.module.dictionary,
                                       std::move(items), m_setup.origin);
    connect(m_job.get(), &WriteJob::finished, this, [this, gains, then](bool complete) {
        const std::vector<WriteItem> done = m_job->items();
        m_job.release()->deleteLater();
        m_current = complete ? std::optional<Gains>(gains) : std::nullopt;
        emit written(m_setup.module.address, done);
        then(complete);
    });
    // The step test may have just written back an EEPROM row (the source E17); the module takes
    // the next EEPROM write only after its pacing time (DMA Profinet manual §3.4.1), and WriteJob
    // paces only its own writes.
    const auto alive = m_alive;
    QTimer::singleShot(m_setup.module.dictionary->writePacingMs, this, [this, alive] {
        if (*alive && m_job)
            m_job->start();
    });
}

void GuidedTuning::keep()
{
    if (m_state != GuidedState::Proposed || !m_best)
        return;
    if (m_current && *m_current == *m_best)
        return finish(GuidedEnd::Kept, tr("Kept %1.").arg(gainsText(*m_best)));
    askToWrite(*m_best, tr("Keep %1.").arg(gainsText(*m_best)), [this] {
        writeGains(*m_best, [this](bool ok) {
            if (ok)
                return finish(GuidedEnd::Kept, tr("Kept %1.").arg(gainsText(*m_best)));
            restore(tr("The kept gains could not be written."));
        });
    });
}

void GuidedTuning::abort()
{
    if (!isActive())
        return;
    m_abortRequested = true;
    switch (m_state) {
    case GuidedState::Reading:
        if (m_read)
            m_read->cancel();
        return finish(GuidedEnd::Aborted, tr("Aborted before anything was written."));
    case GuidedState::Testing:
        if (m_test && !m_test->isRunning()) { // not started yet (pacing): nothing to stop
            m_test.reset();
            return restore(tr("Aborted."));
        }
        if (m_test)
            m_test->stop(); // onTest restores (it also does when the test just ended)
        return;
    case GuidedState::Writing:   // the write's end restores
    case GuidedState::Restoring: // already on its way back
        return;
    default: return restore(tr("Aborted."));
    }
}

void GuidedTuning::restore(const QString &why)
{
    const GuidedEnd end = m_abortRequested ? GuidedEnd::Aborted : GuidedEnd::Failed;
    if (!m_original)
        return finish(end, why);
    setState(GuidedState::Restoring);
    const Gains original = *m_original;
    writeGains(original, [this, why, end, original](bool ok) {
        finish(end, why + QLatin1Char(' ') +
                        (ok ? tr("The original gains are back: %1.").arg(gainsText(original))
                            : tr("The original gains are NOT back (%1): check the module.")
                                  .arg(gainsText(original))));
    });
}

void GuidedTuning::finish(GuidedEnd end, const QString &text)
{
    m_end = end;
    m_status = text;
    setState(GuidedState::Done);
    emit finished(end, text);
}

} // namespace vt::model
