#include "step_control.h"

#include "dict/cooking.h"
#include "model/text_language.h"
#include "widgets/actuator_confirm.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace vt::ui {

StepControl::StepControl(QWidget *parent) : QWidget(parent)
{
    m_title = new QLabel(this);
    m_module = new QComboBox(this);
    m_row = new QComboBox(this);
    // Filled after the first show: sized to the texts they get, not to the empty combo.
    m_module->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_row->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_value = new NumberBox(this);
    m_value->setKeyboardTracking(false);
    m_write = new QPushButton(this);
    m_activate = new QPushButton(this);
    m_activate->setVisible(false);
    m_arm = new QPushButton(this);
    m_arm->setObjectName(QStringLiteral("stepArm"));
    m_arm->setCheckable(true);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *line = new QHBoxLayout;
    line->setContentsMargins(0, 0, 0, 0);
    line->addWidget(m_title);
    line->addWidget(m_module);
    line->addWidget(m_row);
    line->addWidget(m_value);
    line->addWidget(m_write);
    line->addWidget(m_arm);
    line->addWidget(m_activate);
    line->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(line);
    layout->addWidget(m_status);

    connect(m_module, &QComboBox::currentIndexChanged, this, &StepControl::moduleChosen);
    connect(m_row, &QComboBox::currentIndexChanged, this, &StepControl::rowChosen);
    connect(m_write, &QPushButton::clicked, this, &StepControl::writeStep);
    connect(m_activate, &QPushButton::clicked, this, &StepControl::enableBusSetValue);
    connect(m_value, &NumberBox::refused, m_status, &QLabel::setText);
    connect(m_arm, &QPushButton::clicked, this, [this](bool on) { setArmed(on); });
    retranslate();
    updateEnabled();
}

StepControl::~StepControl() = default;

void StepControl::setConnection(model::DeviceAccess *access,
                                const std::vector<model::ModuleInfo> &modules)
{
    clearConnection();
    m_access = access;
    const QSignalBlocker block(m_module);
    std::vector<model::ModuleInfo> without;
    for (const model::ModuleInfo &module : modules) {
        if (!module.dictionary)
            continue;
        if (!model::SetValueStep::setValueRows(*module.dictionary, module.identification.mode)
                 .empty()) {
            m_modules.push_back(module);
            m_module->addItem(tr("Module %1").arg(module.address), module.address);
        } else {
            without.push_back(module);
        }
    }
    if (m_access && m_modules.empty()) {
        // The dictionary says why (e.g. the SD7 in local device mode has no bus set value).
        showStatus([without] {
            QStringList reasons;
            for (const model::ModuleInfo &module : without) {
                const dev::LocalText why = model::SetValueStep::noStepReason(
                    *module.dictionary, module.identification.mode);
                reasons.append(tr("Module %1: %2")
                                   .arg(module.address)
                                   .arg(QString::fromStdString(why.in(model::textLanguage()))));
            }
            return tr("No connected module has a bus set value; the step is not available.") +
                   (reasons.isEmpty() ? QString() : QStringLiteral("\n") + reasons.join('\n'));
        });
    }
    moduleChosen();
}

void StepControl::clearConnection()
{
    m_step.reset(); // a running WriteJob is cancelled with it
    m_access = nullptr;
    m_armed = false;
    showArmed();
    m_modules.clear();
    const QSignalBlocker blockModule(m_module);
    const QSignalBlocker blockRow(m_row);
    m_module->clear();
    m_row->clear();
    m_activate->setVisible(false);
    m_status->clear();
    updateEnabled();
}

const model::ModuleInfo *StepControl::currentModule() const
{
    const int i = m_module->currentIndex();
    return i >= 0 && static_cast<std::size_t>(i) < m_modules.size()
               ? &m_modules[static_cast<std::size_t>(i)]
               : nullptr;
}

std::pair<const dev::ParamMeta *, const dev::SetValueActivation *>
StepControl::activationTarget() const
{
    const model::ModuleInfo *module = currentModule();
    if (!module)
        return {nullptr, nullptr};
    const dev::SetValueActivation *rule = m_step ? m_step->pendingRule() : nullptr;
    if (!rule) {
        const auto rules =
            model::SetValueStep::activationRules(*module->dictionary, module->identification.mode);
        rule = rules.empty() ? nullptr : rules.front();
    }
    return {rule ? model::SetValueStep::ruleWriteRow(*module->dictionary, *rule) : nullptr, rule};
}

const dev::ParamMeta *StepControl::currentRow() const
{
    const model::ModuleInfo *module = currentModule();
    if (!module)
        return nullptr;
    return module->dictionary->find(m_row->currentData().toString().toStdString());
}

void StepControl::moduleChosen()
{
    retranslate(); // the activation button names this module's row
    m_step.reset();
    m_activate->setVisible(false);
    const QSignalBlocker block(m_row);
    m_row->clear();
    if (const model::ModuleInfo *module = currentModule()) {
        for (const dev::ParamMeta *row :
             model::SetValueStep::setValueRows(*module->dictionary, module->identification.mode)) {
            const QString name = QString::fromStdString(row->name);
            m_row->addItem(name, name);
            m_row->setItemData(m_row->count() - 1,
                               QString::fromStdString(row->label.in(model::textLanguage())),
                               Qt::ToolTipRole);
        }
        m_step = std::make_unique<model::SetValueStep>(*m_access, *module);
        m_step->setLanguage(model::textLanguage());
        connect(m_step.get(), &model::SetValueStep::refused, this,
                [this](const QString &reason, bool needsActivation) {
                    const dev::ParamMeta *row = currentRow();
                    const dev::SetValueActivation *rule = activationTarget().second;
                    const dev::ParamMeta *read =
                        rule ? model::SetValueStep::ruleRow(*currentModule()->dictionary, *rule)
                             : nullptr;
                    const std::optional<double> activation = m_step->activation();
                    if (needsActivation && row && read && rule && activation)
                        showStatus([row, read, rule, activation] {
                            return model::SetValueStep::refusalText(*row, *read, *rule, *activation,
                                                                    model::textLanguage());
                        });
                    else
                        m_status->setText(reason);
                    retranslate(); // the button names the rule that was refused
                    m_activate->setVisible(needsActivation);
                    updateEnabled();
                });
        connect(m_step.get(), &model::SetValueStep::written, this, &StepControl::onWritten);
    }
    rowChosen();
}

void StepControl::rowChosen()
{
    if (const dev::ParamMeta *row = currentRow()) {
        const dev::Limits limits = dev::rowLimits(*row);
        const double factor = row->scale.factor;
        m_value->setDecimals(row->scale.decimals);
        m_value->setRange(std::min(limits.min * factor, limits.max * factor),
                          std::max(limits.min * factor, limits.max * factor));
        m_value->setSingleStep(std::pow(10.0, -row->scale.decimals) * 100);
        m_value->setSuffix(row->unit.empty()
                               ? QString()
                               : QStringLiteral(" ") + QString::fromStdString(row->unit));
    }
    updateEnabled();
}

bool StepControl::selectTarget(int module, const QString &rowName)
{
    const int m = m_module->findData(module);
    if (m < 0)
        return false;
    m_module->setCurrentIndex(m);
    const int r = m_row->findData(rowName);
    if (r < 0)
        return false;
    m_row->setCurrentIndex(r);
    return true;
}

void StepControl::setStepValue(double display)
{
    m_value->setValue(display);
}

double StepControl::stepValue() const
{
    return m_value->value();
}

void StepControl::writeStep()
{
    const dev::ParamMeta *row = currentRow();
    if (!m_step || !row || m_step->isBusy())
        return;
    // A refused entry writes nothing (not the box's previous value either).
    const std::optional<double> typed = m_value->number();
    if (!typed) {
        m_status->setText(m_value->refusal());
        return;
    }
    const double factor = row->scale.factor != 0 ? row->scale.factor : 1.0;
    const double raw = std::round(*typed / factor);
    // The device holds whole raw steps: a typed value between two is sent as the nearer one,
    // and the step line says so (10 mm → 9.961 mm at 0.09765625 mm per raw step). A typed value
    // that is the shown value of that step (9.961 mm) was not rounded by the step.
    m_rounding = {};
    const double sent = dev::toDisplay(*row, raw);
    if (std::abs(sent - *typed) > 1e-9 * std::max(1.0, std::abs(*typed))) {
        const QString unit =
            row->unit.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(row->unit);
        m_rounding = {m_value->cleanText() + unit, raw};
    }
    if (m_armed) {
        startStep(*row, raw);
        return;
    }
    const model::ModuleInfo *module = currentModule();
    QString line =
        actuatorWriteLine(module->address, *row, m_access->image().value(module->address, row),
                          dev::RawValue{raw}, model::textLanguage());
    if (!m_rounding.typed.isEmpty()) {
        line += QLatin1Char(' ') +
                tr("(typed %1, rounded to the device resolution)").arg(m_rounding.typed);
        m_status->setText(roundingText(*row, m_rounding));
    }
    confirmActuatorWrites(this, {line}, [this, guard = QPointer<StepControl>(this), row, raw] {
        if (guard && m_step && currentRow() == row)
            startStep(*row, raw);
    });
}

void StepControl::startStep(const dev::ParamMeta &rowRef, double raw)
{
    const dev::ParamMeta *row = &rowRef;
    if (!m_step || m_step->isBusy())
        return;
    m_activate->setVisible(false);
    const model::ModuleInfo *module = currentModule();
    QStringList checked;
    for (const dev::SetValueActivation *rule :
         model::SetValueStep::activationRules(*module->dictionary, module->identification.mode))
        checked << QString::fromStdString(rule->row);
    QString status = checked.isEmpty() ? tr("Writing %1 …").arg(QString::fromStdString(row->name))
                                       : tr("Checking %1, then writing %2 …")
                                             .arg(checked.join(QStringLiteral(", ")),
                                                  QString::fromStdString(row->name));
    if (!m_rounding.typed.isEmpty())
        status += QLatin1Char('\n') + roundingText(*row, m_rounding);
    m_status->setText(status);
    m_step->setLanguage(model::textLanguage());
    m_step->step(*row, raw);
    updateEnabled();
}

void StepControl::enableBusSetValue()
{
    if (!m_step || m_step->isBusy())
        return;
    const model::ModuleInfo *module = currentModule();
    const auto target = activationTarget();
    const dev::ParamMeta *e17 = target.first;
    const dev::SetValueActivation *rule = target.second;
    if (!e17 || !rule)
        return;
    const QString line =
        actuatorWriteLine(module->address, *e17, m_access->image().value(module->address, e17),
                          dev::RawValue{rule->value}, model::textLanguage());
    const QString writing =
        tr("Writing %1 = %2 …")
            .arg(QString::fromStdString(e17->name), QString::fromStdString(dev::formatValue(
                                                        *e17, rule->value, model::textLanguage())));
    confirmActuatorWrites(this, {line}, [this, guard = QPointer<StepControl>(this), writing] {
        if (!guard || !m_step || m_step->isBusy())
            return;
        m_activate->setVisible(false);
        m_status->setText(writing);
        m_step->enableBusSetValue();
        updateEnabled();
    });
}

void StepControl::setArmed(bool armed)
{
    const dev::ParamMeta *row = currentRow();
    const model::ModuleInfo *module = currentModule();
    if (!armed || !row || !module) {
        m_armed = false;
        showArmed();
        return;
    }
    const QString line = tr("Module %1: %2 (%3), every step until disconnect, without asking again")
                             .arg(module->address)
                             .arg(QString::fromStdString(row->name),
                                  QString::fromStdString(row->label.in(model::textLanguage())));
    m_arm->setChecked(false); // checked only once the person agreed
    confirmActuatorWrites(this, {line}, [this, guard = QPointer<StepControl>(this)] {
        if (!guard || !m_access)
            return;
        m_armed = true;
        showArmed();
    });
}

void StepControl::showArmed()
{
    m_arm->setChecked(m_armed);
    m_arm->setText(m_armed ? tr("Armed") : tr("Arm"));
    m_arm->setStyleSheet(m_armed
                             ? QStringLiteral("QPushButton { color: white; background: #c62828; "
                                              "font-weight: bold; }")
                             : QString());
    m_arm->setToolTip(m_armed ? tr("Steps are written without asking until you disarm or "
                                   "disconnect. Click to disarm.")
                              : tr("Arm the step: after one confirmation, steps are written "
                                   "without asking again until disconnect."));
}

QString StepControl::roundingText(const dev::ParamMeta &row, const Rounding &rounding)
{
    return tr("%1 → %2 (device resolution)")
        .arg(rounding.typed,
             QString::fromStdString(dev::formatValue(row, rounding.raw, model::textLanguage())));
}

void StepControl::onWritten(int module, const std::vector<model::WriteItem> &items, bool complete)
{
    // The rounding is said again beside the outcome of the set value it changed.
    const dev::ParamMeta *row = currentRow();
    const Rounding rounding = m_rounding;
    const bool rounded = row && !rounding.typed.isEmpty() &&
                         std::any_of(items.begin(), items.end(),
                                     [row](const model::WriteItem &i) { return i.row == row; });
    showStatus([items, row, rounding, rounded] {
        return rounded ? writtenText(items) + QLatin1Char('\n') + roundingText(*row, rounding)
                       : writtenText(items);
    });
    updateEnabled();
    emit written(module, items, complete);
}

QString StepControl::writtenText(const std::vector<model::WriteItem> &items)
{
    QStringList lines;
    for (const model::WriteItem &item : items) {
        const QString text = model::writeStatusText(item.status);
        const QString reason = model::writeReasonText(item, model::textLanguage());
        lines.append(
            reason.isEmpty()
                ? QStringLiteral("%1: %2").arg(QString::fromStdString(item.row->name), text)
                : QStringLiteral("%1: %2 (%3)")
                      .arg(QString::fromStdString(item.row->name), text, reason));
    }
    return lines.join(QLatin1Char('\n'));
}

QString StepControl::statusText() const
{
    return m_status->text();
}

bool StepControl::activationOffered() const
{
    return !m_activate->isHidden();
}

bool StepControl::isBusy() const
{
    return m_step && m_step->isBusy();
}

void StepControl::updateEnabled()
{
    const bool ready = m_step && currentRow() && !m_step->isBusy();
    m_module->setEnabled(!isBusy() && m_module->count() > 0);
    m_row->setEnabled(ready);
    m_value->setEnabled(ready);
    m_write->setEnabled(ready);
    m_activate->setEnabled(ready);
    m_arm->setEnabled(m_armed || ready);
}

void StepControl::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void StepControl::retranslate()
{
    m_title->setText(tr("Step:"));
    m_write->setText(tr("Write step"));
    for (int i = 0; i < m_module->count(); ++i)
        m_module->setItemText(i, tr("Module %1").arg(m_module->itemData(i).toInt()));
    m_write->setToolTip(
        tr("Writes the bus set value (range-checked, read back) and marks it on the time axis, "
           "after checking that the module takes its set value from the bus."));
    showArmed();
    const auto target = activationTarget();
    const dev::ParamMeta *row = target.first;
    const dev::SetValueActivation *rule = target.second;
    const QString name = row ? QString::fromStdString(row->name) : QStringLiteral("E17");
    const QString value =
        row && rule ? (rule->state ? QStringLiteral("0x%1").arg(static_cast<int>(rule->value), 4,
                                                                16, QLatin1Char('0'))
                                   : QString::fromStdString(dev::formatValue(
                                         *row, rule->value, model::textLanguage())))
                    : QStringLiteral("2");
    if (rule && rule->state)
        m_activate->setText(
            tr("Switch to %1 (%2 = %3)")
                .arg(QString::fromLatin1(dev::dsp408::stateName(*rule->state)), name, value));
    else
        m_activate->setText(tr("Set %1 = %2").arg(name, value));
    m_activate->setToolTip(
        tr("Makes the bus set value the one that drives the valve (%1 = %2).").arg(name, value));
    if (m_statusRender && m_status->text() == m_statusShown)
        showStatus(m_statusRender);
}

void StepControl::showStatus(std::function<QString()> render)
{
    m_statusRender = std::move(render);
    m_statusShown = m_statusRender();
    m_status->setText(m_statusShown);
}

} // namespace vt::ui
