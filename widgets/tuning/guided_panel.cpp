#include "guided_panel.h"

#include "dict/cooking.h"
#include "model/text_language.h"
#include "model/tuning/analysis_texts.h"
#include "model/tuning/workbench_rows.h"
#include "widgets/actuator_confirm.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

namespace vt::ui {

namespace {

QString num(double v, int decimals)
{
    return std::isfinite(v) ? QLocale().toString(v, 'f', decimals) : QStringLiteral("–");
}

QString value(const dev::ParamMeta *row, double raw)
{
    return row ? QString::fromStdString(dev::formatValue(*row, raw, model::textLanguage()))
               : QStringLiteral("–");
}

} // namespace

GuidedPanel::GuidedPanel(GuidedHooks hooks, QWidget *parent)
    : QWidget(parent), m_hooks(std::move(hooks))
{
    auto *outer = new QHBoxLayout(this);
    auto *column = new QVBoxLayout;
    auto *form = new QFormLayout;
    m_targetLabel = new QLabel(this);
    m_target = new QComboBox(this);
    m_target->addItem(QString(), static_cast<int>(model::GainTarget::Kind::MaxOvershoot));
    m_target->addItem(QString(),
                      static_cast<int>(model::GainTarget::Kind::FastestWithoutOvershoot));
    form->addRow(m_targetLabel, m_target);
    m_overshootLabel = new QLabel(this);
    m_overshoot = new NumberBox(this);
    m_overshoot->setDecimals(1);
    m_overshoot->setRange(0.5, 80);
    m_overshoot->setValue(5);
    form->addRow(m_overshootLabel, m_overshoot);
    m_iterationsLabel = new QLabel(this);
    m_iterations = new NumberBox(this);
    m_iterations->setDecimals(0);
    m_iterations->setRange(1, 20);
    m_iterations->setValue(6);
    form->addRow(m_iterationsLabel, m_iterations);
    m_allowLabel = new QLabel(this);
    m_allowLabel->setWordWrap(true);
    m_allow = new NumberBox(this);
    m_allow->setDecimals(0);
    m_allow->setRange(0, 20);
    form->addRow(m_allowLabel, m_allow);
    column->addLayout(form);
    m_stepLabel = new QLabel(this);
    m_stepLabel->setWordWrap(true);
    column->addWidget(m_stepLabel);
    auto *buttons = new QHBoxLayout;
    m_start = new QPushButton(this);
    m_keep = new QPushButton(this);
    m_abort = new QPushButton(this);
    buttons->addWidget(m_start);
    buttons->addWidget(m_keep);
    buttons->addWidget(m_abort);
    column->addLayout(buttons);
    column->addStretch(1);
    outer->addLayout(column, 2);
    // The status (it can be long: a refusal quotes the manual) goes under the table, where it
    // cannot squeeze the form.
    auto *right = new QVBoxLayout;
    m_table = new QTableWidget(this);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setColumnCount(6);
    right->addWidget(m_table, 1);
    m_statusLabel = new QLabel(this);
    m_statusLabel->setWordWrap(true);
    m_statusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    right->addWidget(m_statusLabel);
    outer->addLayout(right, 3);

    connect(m_target, &QComboBox::currentIndexChanged, this, &GuidedPanel::updateEnabled);
    connect(m_start, &QPushButton::clicked, this, &GuidedPanel::start);
    connect(m_keep, &QPushButton::clicked, this, &GuidedPanel::keep);
    connect(m_abort, &QPushButton::clicked, this, &GuidedPanel::abort);
    connect(m_allow, &NumberBox::valueChanged, this, [this](double n) {
        if (m_tuning && m_tuning->isActive())
            m_tuning->allowNext(static_cast<int>(std::lround(n)));
    });
    retranslate();
    updateEnabled();
}

GuidedPanel::~GuidedPanel() = default;

void GuidedPanel::setTarget(const model::GainTarget &target)
{
    m_target->setCurrentIndex(m_target->findData(static_cast<int>(target.kind)));
    m_overshoot->setValue(target.maxOvershootPct);
}

void GuidedPanel::setMaxIterations(int n)
{
    m_iterations->setValue(n);
}

void GuidedPanel::setAllowance(int n)
{
    m_allow->setValue(n);
}

void GuidedPanel::setStatus(const QString &text)
{
    m_status = text;
    m_statusLabel->setText(text);
}

void GuidedPanel::updateEnabled()
{
    const bool active = isActive();
    const bool proposed = active && m_tuning->state() == model::GuidedState::Proposed;
    m_start->setEnabled(!active);
    m_keep->setEnabled(proposed && m_tuning->best().has_value());
    m_abort->setEnabled(active);
    m_target->setEnabled(!active);
    m_overshoot->setEnabled(!active && m_target->currentData().toInt() ==
                                           static_cast<int>(model::GainTarget::Kind::MaxOvershoot));
    m_iterations->setEnabled(!active);
}

void GuidedPanel::start()
{
    if (isActive())
        return;
    model::DeviceAccess *access = m_hooks.access();
    const model::ModuleInfo *module = m_hooks.module();
    const dev::ParamMeta *row = m_hooks.setValue();
    if (!access || !module || !row)
        return setStatus(tr("Connect and choose a module and its set value first."));
    if (m_hooks.busy())
        return setStatus(tr("A test is running; start the guided tuning after it."));
    const auto spec = m_hooks.signal();
    if (!spec || spec->kind != model::SignalKind::Step)
        return setStatus(tr("Choose a step in the signal form: the guided tuning measures its "
                            "up step (From, To, Hold)."));
    model::GuidedSetup setup;
    setup.module = *module;
    setup.setValueRow = row;
    setup.gains = model::gainRows(*module->dictionary, *row);
    const std::string &mode = module->identification.mode;
    setup.channels = model::recordedRows(*module->dictionary, mode, *row);
    setup.actualRow = model::responseRow(*module->dictionary, mode, *row);
    setup.step = *spec;
    setup.step.direction = model::StepDirection::Up;
    setup.step.repeats = 1;
    setup.rateHz = m_hooks.rateHz();
    setup.window = m_hooks.window();
    setup.target = {static_cast<model::GainTarget::Kind>(m_target->currentData().toInt()),
                    m_overshoot->value()};
    setup.maxIterations = static_cast<int>(std::lround(m_iterations->value()));
    if (const QString problem = model::GuidedTuning::setupProblem(setup); !problem.isEmpty())
        return setStatus(problem);

    const dev::Language lang = model::textLanguage();
    const auto before = access->image().value(module->address, row);
    const QStringList lines = {
        actuatorWriteLine(module->address, *row, before,
                          dev::RawValue{model::setValueRaw(*row, setup.step.to)}, lang),
        tr("Guided tuning: up to %1 steps from %2 to %3, each held %4 s; every change of %5 is "
           "asked for (or allowed); Abort puts the gains back, and %6 is written back after "
           "each step.")
            .arg(setup.maxIterations)
            .arg(QString::fromStdString(
                     dev::formatValue(*row, model::setValueRaw(*row, setup.step.from), lang)),
                 QString::fromStdString(
                     dev::formatValue(*row, model::setValueRaw(*row, setup.step.to), lang)),
                 num(setup.step.hold, 2), QString::fromStdString(setup.gains.p->name),
                 QString::fromStdString(row->name))};
    confirmActuatorWrites(this, lines, [this, setup, guard = QPointer<GuidedPanel>(this)] {
        if (guard)
            begin(setup);
    });
}

void GuidedPanel::begin(model::GuidedSetup setup)
{
    model::DeviceAccess *access = m_hooks.access();
    if (!access || isActive())
        return;
    const auto guard = QPointer<GuidedPanel>(this);
    auto confirm = [this, guard](const QStringList &lines, std::function<void(bool)> answer) {
        if (!guard)
            return;
        confirmActuatorWrites(
            this, lines, [answer] { answer(true); }, [answer] { answer(false); });
    };
    if (m_tuning)
        m_tuning.release()->deleteLater(); // it may be the sender of the signal that ended it
    m_tuning = std::make_unique<model::GuidedTuning>(*access, std::move(setup), confirm);
    m_tuning->allowNext(static_cast<int>(std::lround(m_allow->value())));
    m_table->setRowCount(0);
    connect(m_tuning.get(), &model::GuidedTuning::iterationDone, this, &GuidedPanel::addIteration);
    connect(m_tuning.get(), &model::GuidedTuning::written, this,
            [this](int module, const std::vector<model::WriteItem> &items) {
                if (m_hooks.written)
                    m_hooks.written(module, items);
            });
    connect(m_tuning.get(), &model::GuidedTuning::stateChanged, this, [this] {
        if (!m_tuning)
            return;
        if (m_tuning->state() == model::GuidedState::Testing)
            setStatus(
                tr("Iteration %1: measuring the step…").arg(m_tuning->iterations().size() + 1));
        else
            setStatus(m_tuning->statusText());
        {
            const QSignalBlocker block(m_allow);
            m_allow->setValue(m_tuning->allowance());
        }
        updateEnabled();
        emit activeChanged(isActive());
        if (m_tuning->state() == model::GuidedState::Done && m_tuning->needsSource() &&
            !m_tuning->setup().switchSource)
            offerSourceSwitch();
    });
    m_tuning->start();
    updateEnabled();
}

void GuidedPanel::offerSourceSwitch()
{
    // The set-value source differs (the status quotes the manual): ask, then start again
    // switching it for each step and back after it, as the workbench's own tests do.
    model::GuidedSetup again = m_tuning->setup();
    again.switchSource = true;
    const QStringList lines = {
        m_tuning->statusText(),
        tr("Switch the set-value source for each step and put it back afterwards?")};
    confirmActuatorWrites(this, lines, [this, again, guard = QPointer<GuidedPanel>(this)] {
        if (guard)
            begin(again);
    });
}

void GuidedPanel::addIteration(int index)
{
    const auto &its = m_tuning->iterations();
    if (index < 0 || index >= static_cast<int>(its.size()))
        return;
    const model::GuidedIteration &it = its[static_cast<std::size_t>(index)];
    const model::GuidedSetup &s = m_tuning->setup();
    const int r = m_table->rowCount();
    m_table->setRowCount(r + 1);
    const QStringList cells = {QString::number(index + 1),
                               value(s.gains.p, it.gains.p),
                               s.gains.i ? value(s.gains.i, it.gains.i) : QStringLiteral("–"),
                               it.metrics   ? num(it.metrics->overshootPct, 1)
                               : it.problem ? model::stepProblemText(*it.problem)
                                            : QStringLiteral("–"),
                               it.metrics ? num(it.metrics->riseTime, 3) : QStringLiteral("–"),
                               it.metrics ? num(it.metrics->settlingTime2, 3)
                                          : QStringLiteral("–")};
    for (int c = 0; c < cells.size(); ++c) {
        auto *item = new QTableWidgetItem(cells[c]);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        if (c > 0)
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(r, c, item);
    }
    if (m_hooks.addRun && it.run)
        m_hooks.addRun(std::make_unique<model::TuningRun>(*it.run), index > 0);
}

void GuidedPanel::keep()
{
    if (m_tuning)
        m_tuning->keep();
}

void GuidedPanel::abort()
{
    if (m_tuning)
        m_tuning->abort();
}

void GuidedPanel::clearConnection()
{
    if (isActive())
        m_tuning->abort();
    m_tuning.reset();
    updateEnabled();
    emit activeChanged(false);
}

void GuidedPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void GuidedPanel::retranslate()
{
    m_targetLabel->setText(tr("Target"));
    m_target->setItemText(0, tr("Overshoot at most"));
    m_target->setItemText(1, tr("Fastest without overshoot"));
    m_overshootLabel->setText(tr("Overshoot limit (%)"));
    m_iterationsLabel->setText(tr("Iterations at most"));
    m_allowLabel->setText(tr("Allow the next gain changes without asking"));
    m_stepLabel->setText(tr("Each iteration runs the up step of the signal form (From, To, Hold), "
                            "reads the overshoot and proposes the next P gain; the I portion is "
                            "kept. Keep leaves the chosen gains on the device, Abort puts the "
                            "original ones back."));
    m_start->setText(tr("Start Guided Tuning"));
    m_keep->setText(tr("Keep"));
    m_abort->setText(tr("Abort"));
    m_table->setHorizontalHeaderLabels({tr("Iteration"), tr("P gain"), tr("I portion"),
                                        tr("Overshoot (%)"), tr("Rise time (s)"),
                                        tr("Settling 2 % (s)")});
    // Numbers follow the language: the table is written again.
    if (m_tuning) {
        m_table->setRowCount(0);
        const auto addRun = std::exchange(m_hooks.addRun, {});
        for (int i = 0; i < static_cast<int>(m_tuning->iterations().size()); ++i)
            addIteration(i);
        m_hooks.addRun = addRun;
    }
}

} // namespace vt::ui
