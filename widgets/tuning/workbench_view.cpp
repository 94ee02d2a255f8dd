#include "workbench_view.h"

#include "bode_plot.h"
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "guided_panel.h"
#include "model/monitor/set_value_step.h"
#include "model/text_language.h"
#include "model/tuning/workbench_rows.h"
#include "reference_panel.h"
#include "response_plot.h"
#include "run_list.h"
#include "run_results_tabs.h"
#include "signal_form.h"
#include "widgets/actuator_confirm.h"
#include "widgets/number_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace vt::ui {

namespace {

constexpr int kRedrawMs = 40; // ≤ 25 redraws/s (STYLE.md rule 10)

QString num(double v, int decimals)
{
    return std::isfinite(v) ? QLocale().toString(v, 'f', decimals) : QStringLiteral("–");
}

QString rowText(const dev::ParamMeta &row)
{
    const QString label = QString::fromStdString(row.label.in(model::textLanguage()));
    return label.isEmpty() ? QString::fromStdString(row.name)
                           : QStringLiteral("%1 (%2)").arg(QString::fromStdString(row.name), label);
}

} // namespace

WorkbenchView::WorkbenchView(QWidget *parent) : QWidget(parent)
{
    build();
    m_redraw.setSingleShot(true);
    connect(&m_redraw, &QTimer::timeout, this, &WorkbenchView::refreshLive);
    auto *esc = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    esc->setContext(Qt::WindowShortcut);
    connect(esc, &QShortcut::activated, this, [this] {
        if (isRunning())
            stop();
        m_reference->stop();
    });
    retranslate();
    updateEnabled();
}

WorkbenchView::~WorkbenchView() = default;

void WorkbenchView::build()
{
    auto *outer = new QHBoxLayout(this);
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    outer->addWidget(splitter);

    // Left: what to test (scrolls when the dock is low), then Start / Stop and the outcome, which
    // stay in view.
    auto *left = new QWidget(splitter);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(left);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *settings = new QWidget(scroll);
    auto *column = new QVBoxLayout(settings);
    auto *target = new QFormLayout;
    m_moduleLabel = new QLabel(settings);
    m_module = new QComboBox(settings);
    target->addRow(m_moduleLabel, m_module);
    m_setValueLabel = new QLabel(settings);
    m_setValue = new QComboBox(settings);
    target->addRow(m_setValueLabel, m_setValue);
    m_responseLabel = new QLabel(settings);
    m_responseLabel->setWordWrap(true);
    target->addRow(m_responseLabel);
    column->addLayout(target);
    m_form = new SignalForm(settings);
    column->addWidget(m_form);
    auto *limits = new QFormLayout;
    m_rateLabel = new QLabel(settings);
    m_rate = new NumberBox(settings);
    m_rate->setDecimals(0);
    m_rate->setRange(0, model::kMaxRateHz);
    m_rate->setValue(0);
    limits->addRow(m_rateLabel, m_rate);
    m_useWindow = new QCheckBox(settings);
    m_window = new NumberBox(settings);
    m_window->setDecimals(3);
    m_window->setRange(0.001, 100);
    m_window->setValue(1);
    limits->addRow(m_useWindow, m_window);
    column->addLayout(limits);
    m_runs = new RunList(settings);
    column->addWidget(m_runs, 1);
    scroll->setWidget(settings);
    leftLayout->addWidget(scroll, 1);
    auto *buttons = new QHBoxLayout;
    m_start = new QPushButton(left);
    m_stop = new QPushButton(left);
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    leftLayout->addLayout(buttons);
    m_statusLabel = new QLabel(left);
    m_statusLabel->setWordWrap(true);
    m_statusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_statusLabel->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    leftLayout->addWidget(m_statusLabel);

    // Right: the plot over the results, the plot taking most of the height.
    auto *right = new QSplitter(Qt::Vertical, splitter);
    m_plots = new QStackedWidget(right);
    m_response = new ResponsePlot(m_plots);
    m_bode = new BodePlot(m_plots);
    m_plots->addWidget(m_response);
    m_plots->addWidget(m_bode);
    m_tabs = new RunResultsTabs(right);
    buildGuided();
    buildReference();
    right->setStretchFactor(0, 3);
    right->setStretchFactor(1, 2);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);

    connect(m_module, &QComboBox::currentIndexChanged, this, &WorkbenchView::moduleChosen);
    connect(m_setValue, &QComboBox::currentIndexChanged, this, &WorkbenchView::setValueChosen);
    connect(m_start, &QPushButton::clicked, this, &WorkbenchView::start);
    connect(m_stop, &QPushButton::clicked, this, &WorkbenchView::stop);
    connect(m_useWindow, &QCheckBox::toggled, this, &WorkbenchView::updateEnabled);
    connect(m_runs, &RunList::selectionChanged, this, &WorkbenchView::showCurrent);
    connect(m_runs, &RunList::statusMessage, this, [this](const QString &text) {
        m_status = text;
        m_statusLabel->setText(text);
    });
    connect(m_form, &SignalForm::changed, this, &WorkbenchView::updateEnabled);
}

void WorkbenchView::setConnection(model::DeviceAccess *access,
                                  const std::vector<model::ModuleInfo> &modules)
{
    if (isRunning())
        stop();
    m_access = access;
    m_modules.clear();
    for (const model::ModuleInfo &m : modules)
        if (m.dictionary && !model::testSetValueRows(*m.dictionary, m.identification.mode).empty())
            m_modules.push_back(m);
    const QSignalBlocker block(m_module);
    m_module->clear();
    for (const model::ModuleInfo &m : m_modules)
        m_module->addItem(tr("Module %1 (%2)")
                              .arg(m.address)
                              .arg(QString::fromStdString(m.identification.family)),
                          m.address);
    moduleChosen();
    updateEnabled();
}

void WorkbenchView::clearConnection()
{
    // A running test ends with its restore; the access goes with the connection, so the restore
    // is tried now and the outcome says whether it arrived.
    if (m_test && m_test->isRunning())
        m_test->stop();
    m_test.reset();
    m_guided->clearConnection();
    m_reference->clearConnection();
    m_live.reset();
    m_access = nullptr;
    m_modules.clear();
    const QSignalBlocker block(m_module);
    m_module->clear();
    m_setValue->clear();
    updateEnabled();
}

bool WorkbenchView::selectTarget(int module, const QString &setValueRow)
{
    const int m = m_module->findData(module);
    if (m < 0)
        return false;
    m_module->setCurrentIndex(m);
    const int r = m_setValue->findData(setValueRow);
    if (r < 0)
        return false;
    m_setValue->setCurrentIndex(r);
    return true;
}

void WorkbenchView::setRate(double hz)
{
    m_rate->setValue(hz);
}

void WorkbenchView::setWindow(std::optional<double> window)
{
    m_useWindow->setChecked(window.has_value());
    if (window)
        m_window->setValue(*window);
}

const model::ModuleInfo *WorkbenchView::currentModule() const
{
    const int i = m_module->currentIndex();
    return i >= 0 && i < static_cast<int>(m_modules.size())
               ? &m_modules[static_cast<std::size_t>(i)]
               : nullptr;
}

const dev::ParamMeta *WorkbenchView::currentSetValue() const
{
    const model::ModuleInfo *m = currentModule();
    if (!m)
        return nullptr;
    return m->dictionary->find(m_setValue->currentData().toString().toStdString());
}

void WorkbenchView::moduleChosen()
{
    const QSignalBlocker block(m_setValue);
    m_setValue->clear();
    if (const model::ModuleInfo *m = currentModule())
        for (const dev::ParamMeta *row :
             model::testSetValueRows(*m->dictionary, m->identification.mode))
            m_setValue->addItem(rowText(*row), QString::fromStdString(row->name));
    setValueChosen();
}

void WorkbenchView::setValueChosen()
{
    const model::ModuleInfo *m = currentModule();
    const dev::ParamMeta *row = currentSetValue();
    if (m && row) {
        const dev::Limits limits = dev::rowLimits(*row);
        const double f = row->scale.factor != 0 ? row->scale.factor : 1.0;
        m_window->setSuffix(
            row->unit.empty() ? QString() : QLatin1Char(' ') + QString::fromStdString(row->unit));
        m_form->setSetValue(QString::fromStdString(row->unit), row->scale.decimals,
                            std::min(limits.min * f, limits.max * f),
                            std::max(limits.min * f, limits.max * f));
        m_reference->setSetValue(QString::fromStdString(row->unit), row->scale.decimals,
                                 std::min(limits.min * f, limits.max * f),
                                 std::max(limits.min * f, limits.max * f));
        const dev::ParamMeta *answer =
            model::responseRow(*m->dictionary, m->identification.mode, *row);
        m_responseLabel->setText(
            answer ? tr("Response: %1").arg(rowText(*answer))
                   : tr("The dictionary names no response for %1: the test records, "
                        "but has nothing to analyse.")
                         .arg(QString::fromStdString(row->name)));
    } else {
        m_responseLabel->setText(m_access ? tr("No module with a set value a test can drive.")
                                          : tr("Connect to a device to run a test."));
    }
    updateEnabled();
}

void WorkbenchView::updateEnabled()
{
    const bool running = isRunning();
    const bool guided = (m_guided && m_guided->isActive()) || referenceActive();
    const bool ready = m_access && currentSetValue() && !running && !guided;
    m_start->setEnabled(ready);
    m_stop->setEnabled(running);
    m_module->setEnabled(!running && !guided);
    m_setValue->setEnabled(!running && !guided);
    m_form->setEnabled(!running);
    m_rate->setEnabled(!running);
    m_useWindow->setEnabled(!running);
    m_window->setEnabled(!running && m_useWindow->isChecked());
    m_runs->setFilesEnabled(!running);
    if (m_reference)
        m_reference->updateEnabled();
}

bool WorkbenchView::isRunning() const
{
    return m_test && m_test->isRunning();
}

const std::vector<std::unique_ptr<model::TuningRun>> &WorkbenchView::runs() const
{
    return m_runs->runs();
}

QTableWidget *WorkbenchView::resultsTable() const
{
    return m_tabs->resultsTable();
}

QTableWidget *WorkbenchView::differencesTable() const
{
    return m_tabs->differencesTable();
}

QString WorkbenchView::statusText() const
{
    return m_status;
}

void WorkbenchView::start()
{
    const model::ModuleInfo *module = currentModule();
    const dev::ParamMeta *row = currentSetValue();
    if (!m_access || !module || !row || isRunning() || m_guided->isActive() || referenceActive())
        return;
    const auto spec = m_form->spec();
    const auto fail = [this](const QString &text) {
        m_status = text;
        m_statusLabel->setText(text);
    };
    if (!spec)
        return fail(m_form->refusal());
    if (spec->kind == model::SignalKind::Step && spec->from == spec->to)
        return fail(tr("A step needs different From and To values."));
    if (spec->kind != model::SignalKind::Step && !(spec->amplitude > 0))
        return fail(tr("The amplitude must be more than 0."));
    if (spec->kind == model::SignalKind::Sweep && !(spec->toHz > spec->fromHz))
        return fail(tr("A sweep needs a To frequency above its From frequency."));
    std::string why;
    const auto signal = model::TestSignal::make(*spec, &why);
    if (!signal)
        return fail(tr("This signal cannot be run: %1").arg(QString::fromStdString(why)));
    model::TestRunSetup setup = model::TestRun::setupFor(*module, *row, *signal);
    setup.rateHz = m_rate->value();
    if (m_useWindow->isChecked())
        setup.window = m_window->value();
    if (const QString problem = model::TestRun::rangeProblem(setup); !problem.isEmpty())
        return fail(problem);

    // The question names the module, the set value, the range the signal will drive it through
    // and how long; the values go back afterwards.
    const auto before = m_access->image().value(module->address, row);
    const dev::Language lang = model::textLanguage();
    const QString rangeLine =
        actuatorWriteLine(module->address, *row, before,
                          dev::RawValue{model::setValueRaw(*row, signal->maximum())}, lang);
    const QStringList lines = {
        rangeLine, tr("%1 test of %2 s between %3 and %4; afterwards %5 is written back.")
                       .arg(m_form->kindText(), num(signal->duration(), 1),
                            QString::fromStdString(dev::formatValue(
                                *row, model::setValueRaw(*row, signal->minimum()), lang)),
                            QString::fromStdString(dev::formatValue(
                                *row, model::setValueRaw(*row, signal->maximum()), lang)),
                            QString::fromStdString(row->name))};
    confirmActuatorWrites(this, lines, [this, setup, guard = QPointer<WorkbenchView>(this)] {
        if (guard)
            begin(setup);
    });
}

void WorkbenchView::begin(model::TestRunSetup setup)
{
    if (!m_access || isRunning())
        return;
    m_live = model::newRun(m_runs->nextNumber(), setup, m_access->image());
    m_test = std::make_unique<model::TestRun>(*m_access, std::move(setup));
    connect(m_test.get(), &model::TestRun::sampled, this, [this] {
        if (!m_redraw.isActive())
            m_redraw.start(kRedrawMs);
    });
    connect(m_test.get(), &model::TestRun::finished, this, &WorkbenchView::onFinished);
    m_plots->setCurrentWidget(m_response);
    m_status = tr("Running…");
    m_statusLabel->setText(m_status);
    m_test->start();
    updateEnabled();
}

void WorkbenchView::stop()
{
    if (m_test)
        m_test->stop();
}

void WorkbenchView::refreshLive()
{
    if (!m_test || !m_live)
        return;
    const model::TestRecording &r = m_test->recording();
    m_response->showLive(*m_live, r);
    m_status = r.setValue.t.size() < 2
                   ? tr("Running: %1 of %2 s; sampled at %3 Hz.")
                         .arg(num(m_test->elapsed(), 1), num(m_test->setup().signal.duration(), 1),
                              num(r.sampleRateHz(), 0))
                   : tr("Running: %1 of %2 s; set value updated at %3 Hz, sampled at %4 Hz.")
                         .arg(num(m_test->elapsed(), 1), num(m_test->setup().signal.duration(), 1),
                              num(r.updateRateHz(), 1), num(r.sampleRateHz(), 0));
    m_statusLabel->setText(m_status);
}

QString WorkbenchView::outcomeText(const model::TestOutcome &o) const
{
    QString what;
    switch (o.end) {
    case model::TestEnd::Finished: what = tr("The test ran to its end."); break;
    case model::TestEnd::Stopped: what = tr("The test was stopped."); break;
    case model::TestEnd::WindowExceeded:
        what = tr("The travel window stopped the test: %1").arg(o.reason);
        break;
    case model::TestEnd::Refused: what = tr("Nothing was written: %1").arg(o.reason); break;
    case model::TestEnd::DeviceError:
        what = tr("The device stopped the test: %1").arg(o.reason);
        break;
    case model::TestEnd::LinkLost: what = tr("The link was lost: %1").arg(o.reason); break;
    }
    QStringList back;
    for (const model::WriteItem &item : o.restore)
        back << tr("%1 back to %2 (%3)")
                    .arg(QString::fromStdString(item.row->name),
                         QString::fromStdString(dev::formatValue(
                             *item.row, dev::rawNumber(item.value), model::textLanguage())),
                         model::writeStatusText(item.status));
    if (!back.isEmpty())
        what +=
            QLatin1Char(' ') +
            (o.restored
                 ? tr("Restored: %1.").arg(back.join(QStringLiteral("; ")))
                 : tr("NOT restored: %1. Check the valve.").arg(back.join(QStringLiteral("; "))));
    return what;
}

void WorkbenchView::onFinished(const model::TestOutcome &outcome)
{
    m_redraw.stop();
    // The engine emitted this from its own code: it goes later, its recording now.
    model::TestRecording recording;
    if (m_test) {
        recording = m_test->recording();
        m_test.release()->deleteLater();
    }
    if (outcome.end == model::TestEnd::Refused && outcome.needsSource && m_live) {
        // The source differs: ask with the manual's reason, then run again switching it for the
        // test (and back after).
        const model::ModuleInfo *module = currentModule();
        const dev::ParamMeta *row = currentSetValue();
        m_status = outcome.reason;
        m_statusLabel->setText(m_status);
        if (!module || !row)
            return;
        const auto spec = m_live->spec;
        QStringList lines;
        for (const model::WriteItem &item : outcome.switchNeeded)
            lines << actuatorWriteLine(module->address, *item.row, item.before, item.value,
                                       model::textLanguage());
        lines << outcome.reason << tr("For the test only: afterwards the values are written back.");
        confirmActuatorWrites(this, lines, [this, spec, guard = QPointer<WorkbenchView>(this)] {
            if (!guard || !m_access)
                return;
            const model::ModuleInfo *m = currentModule();
            const dev::ParamMeta *r = currentSetValue();
            const auto signal = model::TestSignal::make(spec);
            if (!m || !r || !signal)
                return;
            model::TestRunSetup again = model::TestRun::setupFor(*m, *r, *signal);
            again.rateHz = m_rate->value();
            again.switchSource = true;
            if (m_useWindow->isChecked())
                again.window = m_window->value();
            begin(again);
        });
        updateEnabled();
        return;
    }
    if (outcome.end == model::TestEnd::Refused || !m_live) {
        m_lastOutcome = outcome;
        m_status = outcomeText(outcome);
        m_statusLabel->setText(m_status);
        m_live.reset();
        updateEnabled();
        return;
    }
    std::unique_ptr<model::TuningRun> run = std::move(m_live);
    run->recording = std::move(recording);
    run->end = outcome.end;
    run->restored = outcome.restored;
    if (const auto signal = model::TestSignal::make(run->spec))
        run->analysis =
            model::analyseRun(*signal, run->recording, run->responseRow, run->setValueRow);
    m_lastOutcome = outcome;
    m_status = outcomeText(outcome);
    m_statusLabel->setText(m_status);
    emit statusMessage(outcome.restored
                           ? tr("Workbench: run %1 done, values restored.").arg(run->number)
                           : tr("Workbench: run %1 ended, values NOT restored.").arg(run->number));
    if (!outcome.restore.empty())
        emit written(run->module, outcome.restore);
    m_runs->addRun(std::move(run));
    updateEnabled();
}

void WorkbenchView::showCurrent()
{
    const auto runs = m_runs->shownRuns();
    updateEnabled();
    if (runs.empty() || isRunning())
        return;
    const bool frequency = !runs.front()->analysis.points.empty() &&
                           runs.front()->spec.kind != model::SignalKind::Square;
    if (frequency) {
        m_bode->showRuns(runs);
        m_plots->setCurrentWidget(m_bode);
    } else {
        m_response->showRuns(runs);
        m_plots->setCurrentWidget(m_response);
    }
    m_tabs->showRuns(runs);
}

void WorkbenchView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void WorkbenchView::retranslate()
{
    m_moduleLabel->setText(tr("Module"));
    m_setValueLabel->setText(tr("Set value"));
    m_rateLabel->setText(tr("Cycles/s"));
    m_rate->setToolTip(tr("Set-value writes and reads per second; 0: as fast as the link "
                          "allows (at most 1000)."));
    m_rate->setSpecialValueText(tr("as fast as possible"));
    m_useWindow->setText(tr("Travel window"));
    m_window->setToolTip(tr("Stop the test when the actual value leaves the signal's range by "
                            "more than this."));
    m_start->setText(tr("Start Test"));
    m_stop->setText(tr("Stop (Esc)"));
    m_tabs->setTabText(2, tr("Guided tuning"));
    m_tabs->setTabText(3, tr("Reference"));
    for (int i = 0; i < m_module->count() && i < static_cast<int>(m_modules.size()); ++i) {
        const model::ModuleInfo &m = m_modules[static_cast<std::size_t>(i)];
        m_module->setItemText(i, tr("Module %1 (%2)")
                                     .arg(m.address)
                                     .arg(QString::fromStdString(m.identification.family)));
    }
    if (const model::ModuleInfo *m = currentModule())
        for (int i = 0; i < m_setValue->count(); ++i)
            if (const dev::ParamMeta *row =
                    m->dictionary->find(m_setValue->itemData(i).toString().toStdString()))
                m_setValue->setItemText(i, rowText(*row));
    setValueChosen();
    // The last outcome is said again in the new language (the device's or the engine's reason
    // inside it stays as it was said).
    if (m_lastOutcome && !isRunning()) {
        m_status = outcomeText(*m_lastOutcome);
        m_statusLabel->setText(m_status);
    }
    if (!m_runs->runs().empty() && !isRunning())
        showCurrent();
}

} // namespace vt::ui
