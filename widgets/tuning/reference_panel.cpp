#include "reference_panel.h"

#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/text_language.h"
#include "model/tuning/workbench_rows.h"
#include "reference_drift_view.h"
#include "widgets/actuator_confirm.h"
#include "widgets/number_box.h"

#include <QCheckBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

namespace vt::ui {

namespace {

QString num(double v, int decimals)
{
    return std::isfinite(v) ? QLocale().toString(v, 'f', decimals) : QStringLiteral("–");
}

NumberBox *box(QWidget *parent, int decimals, double min, double max, double value)
{
    auto *b = new NumberBox(parent);
    b->setDecimals(decimals);
    b->setRange(min, max);
    b->setValue(value);
    return b;
}

} // namespace

ReferencePanel::ReferencePanel(ReferenceHooks hooks, QWidget *parent)
    : QWidget(parent), m_hooks(std::move(hooks))
{
    auto *outer = new QHBoxLayout(this);
    // Left: the plan, the thresholds and the buttons (the workbench puts the whole panel in a
    // scroll area for a low dock).
    auto *controls = new QWidget(this);
    auto *column = new QVBoxLayout(controls);
    auto *planForm = new QFormLayout;
    planForm->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint); // room for the drift
    const model::DriftThresholds defaults;
    m_centreLabel = new QLabel(controls);
    m_centre = box(controls, 3, -1e6, 1e6, 0);
    planForm->addRow(m_centreLabel, m_centre);
    m_amplitudeLabel = new QLabel(controls);
    m_amplitude = box(controls, 3, 0.001, 1e6, 1);
    planForm->addRow(m_amplitudeLabel, m_amplitude);
    m_holdLabel = new QLabel(controls);
    m_hold = box(controls, 2, 0.05, 60, 1);
    planForm->addRow(m_holdLabel, m_hold);
    m_sweep = new QCheckBox(controls);
    planForm->addRow(m_sweep);
    m_fromLabel = new QLabel(controls);
    m_fromHz = box(controls, 2, 0.01, 500, 0.5);
    planForm->addRow(m_fromLabel, m_fromHz);
    m_toLabel = new QLabel(controls);
    m_toHz = box(controls, 2, 0.02, 500, 10);
    planForm->addRow(m_toLabel, m_toHz);
    column->addLayout(planForm);
    m_thresholdsLabel = new QLabel(controls);
    column->addWidget(m_thresholdsLabel);
    auto *limits = new QFormLayout;
    limits->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    const auto limit = [&](QLabel *&label, NumberBox *&b, double value) {
        label = new QLabel(controls);
        b = box(controls, 1, 0, 1000, value);
        limits->addRow(label, b);
        connect(b, &NumberBox::valueChanged, this, &ReferencePanel::recompute);
    };
    limit(m_riseLabel, m_rise, defaults.riseTimePct);
    limit(m_overshootLabel, m_overshoot, defaults.overshootPoints);
    limit(m_settlingLabel, m_settling, defaults.settlingPct);
    limit(m_errorLabel, m_error, defaults.steadyStatePctOfStep);
    limit(m_bandwidthLabel, m_bandwidth, defaults.bandwidthPct);
    limit(m_phaseLabel, m_phase, defaults.phase90Pct);
    column->addLayout(limits);
    column->addStretch(1);
    column->setContentsMargins(0, 0, 0, 0);
    auto *left = new QVBoxLayout;
    left->addWidget(controls, 1);
    auto *buttons = new QHBoxLayout;
    m_save = new QPushButton(this);
    m_compare = new QPushButton(this);
    m_stop = new QPushButton(this);
    buttons->addWidget(m_save);
    buttons->addWidget(m_compare);
    buttons->addWidget(m_stop);
    left->addLayout(buttons);
    m_statusLabel = new QLabel(this);
    m_statusLabel->setWordWrap(true);
    m_statusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    left->addWidget(m_statusLabel);
    outer->addLayout(left, 0);
    m_view = new ReferenceDriftView(this);
    outer->addWidget(m_view, 1);

    connect(m_sweep, &QCheckBox::toggled, this, &ReferencePanel::updateEnabled);
    connect(m_save, &QPushButton::clicked, this, [this] {
        QString path = QFileDialog::getSaveFileName(this, tr("Save as Reference"), QString(),
                                                    tr("ValveTune references (*.vtref)"));
        if (path.isEmpty())
            return;
        if (!path.endsWith(QStringLiteral(".vtref")))
            path += QStringLiteral(".vtref");
        saveAs(path);
    });
    connect(m_compare, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Compare with Reference"), QString(), tr("ValveTune references (*.vtref)"));
        if (!path.isEmpty())
            compareWith(path);
    });
    connect(m_stop, &QPushButton::clicked, this, &ReferencePanel::stop);
    retranslate();
    updateEnabled();
}

ReferencePanel::~ReferencePanel() = default;

void ReferencePanel::setSetValue(const QString &unit, int decimals, double min, double max)
{
    const QString suffix = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
    for (NumberBox *b : {m_centre, m_amplitude}) {
        b->setDecimals(decimals);
        b->setSuffix(suffix);
    }
    m_centre->setRange(min, max);
    m_amplitude->setRange(std::pow(10.0, -decimals), std::max(max - min, 1e-3) / 2);
}

void ReferencePanel::setPlan(const model::ReferencePlan &plan)
{
    m_centre->setValue(plan.centre);
    m_amplitude->setValue(plan.amplitude);
    m_hold->setValue(plan.hold);
    m_sweep->setChecked(plan.sweep);
    m_fromHz->setValue(plan.fromHz);
    m_toHz->setValue(plan.toHz);
}

model::ReferencePlan ReferencePanel::plan() const
{
    model::ReferencePlan p;
    p.centre = m_centre->value();
    p.amplitude = m_amplitude->value();
    p.hold = m_hold->value();
    p.sweep = m_sweep->isChecked();
    p.fromHz = m_fromHz->value();
    p.toHz = m_toHz->value();
    return p;
}

void ReferencePanel::setThresholds(const model::DriftThresholds &t)
{
    m_rise->setValue(t.riseTimePct);
    m_overshoot->setValue(t.overshootPoints);
    m_settling->setValue(t.settlingPct);
    m_error->setValue(t.steadyStatePctOfStep);
    m_bandwidth->setValue(t.bandwidthPct);
    m_phase->setValue(t.phase90Pct);
}

model::DriftThresholds ReferencePanel::thresholds() const
{
    model::DriftThresholds t;
    t.riseTimePct = m_rise->value();
    t.overshootPoints = m_overshoot->value();
    t.settlingPct = m_settling->value();
    t.steadyStatePctOfStep = m_error->value();
    t.bandwidthPct = m_bandwidth->value();
    t.phase90Pct = m_phase->value();
    return t;
}

void ReferencePanel::setStatus(const QString &text)
{
    m_statusText = {};
    m_status = text;
    m_statusLabel->setText(text);
}

void ReferencePanel::setStatus(std::function<QString()> text)
{
    m_statusText = std::move(text);
    m_status = m_statusText();
    m_statusLabel->setText(m_status);
}

void ReferencePanel::updateEnabled()
{
    const bool active = isActive();
    const bool ready = !active && m_hooks.access() && m_hooks.module() && m_hooks.setValue();
    m_save->setEnabled(ready);
    m_compare->setEnabled(ready);
    m_stop->setEnabled(active);
    for (QWidget *w : std::initializer_list<QWidget *>{m_centre, m_amplitude, m_hold, m_sweep})
        w->setEnabled(!active);
    m_fromHz->setEnabled(!active && m_sweep->isChecked());
    m_toHz->setEnabled(!active && m_sweep->isChecked());
}

void ReferencePanel::saveAs(const QString &path)
{
    model::DeviceAccess *access = m_hooks.access();
    const model::ModuleInfo *module = m_hooks.module();
    const dev::ParamMeta *row = m_hooks.setValue();
    if (isActive())
        return;
    if (!access || !module || !row)
        return setStatus(tr("Connect and choose a module and its set value first."));
    model::ReferenceSetup setup;
    setup.module = *module;
    setup.setValueRow = row;
    m_runningPlan = plan();
    setup.tests = model::referenceTests(m_runningPlan);
    m_path = path;
    ask(setup, Purpose::Save);
}

void ReferencePanel::compareWith(const QString &path)
{
    if (isActive())
        return;
    if (!m_hooks.access())
        return setStatus(tr("Connect and choose a module and its set value first."));
    QString why;
    auto loaded = model::loadReference(path, *dev::builtinDictionaries(), &why);
    if (!loaded)
        return setStatus(why);
    // The module the reference was taken on when the node has it, else the workbench's choice.
    const model::ModuleInfo *module = m_hooks.moduleAt(loaded->file.address);
    if (!module)
        module = m_hooks.module();
    if (!module)
        return setStatus(tr("Connect and choose a module and its set value first."));
    if (const QString problem = model::referenceFitProblem(loaded->file, *module);
        !problem.isEmpty())
        return setStatus([file = loaded->file, fit = *module] {
            return tr("This reference does not fit: %1").arg(model::referenceFitProblem(file, fit));
        });
    m_reference = std::move(*loaded);
    m_comparison.reset();
    m_now.clear();
    m_view->show(*m_reference, {}, std::nullopt);
    model::ReferenceSetup setup;
    setup.module = *module;
    setup.setValueRow = module->dictionary->find(m_reference->file.setValue);
    setup.tests = m_reference->tests();
    m_path = path;
    ask(setup, Purpose::Compare);
}

void ReferencePanel::ask(const model::ReferenceSetup &given, Purpose purpose)
{
    model::ReferenceSetup setup = given;
    setup.rateHz = m_hooks.rateHz();
    setup.window = m_hooks.window();
    if (m_hooks.busy())
        return setStatus(tr("A test is running; start the reference tests after it."));
    if (const QString problem = model::ReferenceSession::setupProblem(setup); !problem.isEmpty())
        return setStatus(problem);
    const dev::ParamMeta &row = *setup.setValueRow;
    double lo = INFINITY;
    double hi = -INFINITY;
    QStringList tests;
    for (const model::ReferenceTestSpec &t : setup.tests) {
        const auto signal = model::TestSignal::make(t.spec);
        lo = std::min(lo, signal->minimum());
        hi = std::max(hi, signal->maximum());
        tests << (t.spec.kind == model::SignalKind::Sweep
                      ? tr("a stepped-sine sweep from %1 to %2 Hz")
                            .arg(num(t.spec.fromHz, 2), num(t.spec.toHz, 2))
                      : tr("a step up and a step down, each level held %1 s")
                            .arg(num(t.spec.hold, 2)));
    }
    const dev::Language lang = model::textLanguage();
    const auto shown = [&](double v) {
        return QString::fromStdString(dev::formatValue(row, model::setValueRaw(row, v), lang));
    };
    const auto before = m_hooks.access()->image().value(setup.module.address, &row);
    const QStringList lines = {
        actuatorWriteLine(setup.module.address, row, before,
                          dev::RawValue{model::setValueRaw(row, hi)}, lang),
        tr("Reference tests: %1; between %2 and %3, about %4 s in all; afterwards %5 is written "
           "back.")
            .arg(tests.join(tr(" and ")), shown(lo), shown(hi),
                 num(model::ReferenceSession::duration(setup), 0),
                 QString::fromStdString(row.name))};
    confirmActuatorWrites(this, lines,
                          [this, setup, purpose, guard = QPointer<ReferencePanel>(this)] {
                              if (guard)
                                  run(setup, purpose);
                          });
}

void ReferencePanel::run(model::ReferenceSetup setup, Purpose purpose)
{
    model::DeviceAccess *access = m_hooks.access();
    if (!access || isActive() || m_hooks.busy())
        return;
    m_purpose = purpose;
    m_session = std::make_unique<model::ReferenceSession>(*access, std::move(setup));
    connect(m_session.get(), &model::ReferenceSession::progress, this,
            [this] { setStatus(m_session->statusText()); });
    connect(m_session.get(), &model::ReferenceSession::written, this,
            [this](int module, const std::vector<model::WriteItem> &items) {
                m_hooks.written(module, items);
            });
    connect(m_session.get(), &model::ReferenceSession::finished, this, &ReferencePanel::onFinished);
    m_session->start();
    updateEnabled();
    emit activeChanged(isActive());
}

void ReferencePanel::onFinished(bool complete)
{
    // The session emitted this from its own code: it goes later, its results now.
    model::ReferenceSession *session = m_session.release();
    session->deleteLater();
    updateEnabled();
    emit activeChanged(false);
    const model::ReferenceSetup setup = session->setup();
    if (!complete && session->needsSource() && !setup.switchSource) {
        // The source differs: ask with the manual's reason, then run the set again switching it
        // for the tests (and back after each).
        setStatus(session->lastOutcome().reason);
        QStringList lines;
        for (const model::WriteItem &item : session->lastOutcome().switchNeeded)
            lines << actuatorWriteLine(setup.module.address, *item.row, item.before, item.value,
                                       model::textLanguage());
        lines << session->lastOutcome().reason
              << tr("For the tests only: afterwards the values are written back.");
        const Purpose purpose = m_purpose;
        confirmActuatorWrites(this, lines,
                              [this, setup, purpose, guard = QPointer<ReferencePanel>(this)] {
                                  if (!guard)
                                      return;
                                  model::ReferenceSetup again = setup;
                                  again.switchSource = true;
                                  run(again, purpose);
                              });
        return;
    }
    if (!complete)
        return setStatus(session->statusText());
    if (m_purpose == Purpose::Save) {
        model::Reference made =
            model::makeReference(setup.module, *setup.setValueRow, m_runningPlan,
                                 session->settings(), session->runs(), model::textLanguage());
        if (const QString error = model::saveReference(made, m_path); !error.isEmpty())
            return setStatus(error);
        m_reference = std::move(made);
        m_comparison.reset();
        m_now.clear();
        m_view->show(*m_reference, {}, std::nullopt);
        return setStatus([this, path = m_path, settings = m_reference->file.settings.size(),
                          runs = m_reference->runs.size()] {
            return tr("Reference saved to %1: %2 settings, %3 test(s); the set value is restored.")
                .arg(path)
                .arg(settings)
                .arg(runs);
        });
    }
    m_now = session->runs();
    m_nowSettings = session->settings();
    recompute();
    setStatus([this, path = m_path, file = m_reference->file, module = setup.module] {
        QStringList notes = model::referenceNotes(file, module);
        notes.prepend(tr("Compared with %1; the set value is restored.").arg(path));
        return notes.join(QLatin1Char(' '));
    });
}

void ReferencePanel::recompute()
{
    if (!m_reference || m_now.empty())
        return;
    m_comparison = model::compareWithReference(*m_reference, m_now, m_nowSettings, thresholds(),
                                               model::textLanguage());
    m_view->show(*m_reference, m_now, m_comparison);
}

void ReferencePanel::stop()
{
    if (m_session)
        m_session->stop();
}

void ReferencePanel::clearConnection()
{
    if (m_session && m_session->isActive())
        m_session->stop();
    m_session.reset();
    updateEnabled();
}

void ReferencePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ReferencePanel::retranslate()
{
    m_centreLabel->setText(tr("Centre"));
    m_centre->setToolTip(tr("The set value the tests move around."));
    m_amplitudeLabel->setText(tr("Amplitude"));
    m_amplitude->setToolTip(tr("The steps go from centre − amplitude to centre + amplitude and "
                               "back; the sweep swings by ± amplitude."));
    m_holdLabel->setText(tr("Hold (s)"));
    m_hold->setToolTip(tr("How long each level of the steps is held: several settling times."));
    m_sweep->setText(tr("Also a stepped-sine sweep"));
    m_fromLabel->setText(tr("Sweep from (Hz)"));
    m_toLabel->setText(tr("Sweep to (Hz)"));
    m_thresholdsLabel->setText(tr("<b>Drift thresholds</b>"));
    m_riseLabel->setText(tr("Rise time ± (%)"));
    m_overshootLabel->setText(tr("Overshoot + (points)"));
    m_settlingLabel->setText(tr("Settling time ± (%)"));
    m_errorLabel->setText(tr("Steady-state error ± (% of the step)"));
    m_bandwidthLabel->setText(tr("Bandwidth ± (%)"));
    m_phaseLabel->setText(tr("−90° frequency ± (%)"));
    m_save->setText(tr("Save as Reference…"));
    m_compare->setText(tr("Compare with Reference…"));
    m_stop->setText(tr("Stop"));
    if (m_statusText) {
        m_status = m_statusText();
        m_statusLabel->setText(m_status);
    }
    if (m_status.isEmpty())
        m_statusLabel->setText(tr("A reference keeps the module's settings and its responses to "
                                  "these tests in one file; comparing repeats the tests."));
}

} // namespace vt::ui
