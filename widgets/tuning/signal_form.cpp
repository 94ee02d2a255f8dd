#include "signal_form.h"

#include "widgets/number_box.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace vt::ui {

namespace {

constexpr model::SignalKind kKinds[] = {model::SignalKind::Step, model::SignalKind::Square,
                                        model::SignalKind::Triangle, model::SignalKind::Sine,
                                        model::SignalKind::Sweep};
constexpr model::StepDirection kDirections[] = {
    model::StepDirection::Up, model::StepDirection::Down, model::StepDirection::Both};

int pageOf(model::SignalKind kind)
{
    switch (kind) {
    case model::SignalKind::Step: return 0;
    case model::SignalKind::Sweep: return 2;
    default: return 1;
    }
}

} // namespace

SignalForm::SignalForm(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *top = new QFormLayout;
    m_kind = new QComboBox(this);
    addLabelled(top, m_kind);
    layout->addLayout(top);
    m_pages = new QStackedWidget(this);
    layout->addWidget(m_pages);

    auto page = [this](QFormLayout *&form) {
        auto *w = new QWidget(m_pages);
        form = new QFormLayout(w);
        form->setContentsMargins(0, 0, 0, 0);
        m_pages->addWidget(w);
    };
    page(m_step);
    m_from = valueBox(3);
    m_to = valueBox(3);
    m_hold = valueBox(2);
    m_hold->setRange(0.01, 600);
    m_hold->setValue(1);
    m_repeats = countBox(1, 1000, 1);
    m_direction = new QComboBox(this);
    addLabelled(m_step, m_from);
    addLabelled(m_step, m_to);
    addLabelled(m_step, m_hold);
    addLabelled(m_step, m_repeats);
    addLabelled(m_step, m_direction);

    page(m_periodic);
    m_amplitude = valueBox(3);
    m_offset = valueBox(3);
    m_frequency = valueBox(3);
    m_frequency->setRange(0.001, 1000);
    m_frequency->setValue(1);
    m_cycles = countBox(1, 10'000, 3);
    m_settling = countBox(0, 10'000, 1);
    addLabelled(m_periodic, m_amplitude);
    addLabelled(m_periodic, m_offset);
    addLabelled(m_periodic, m_frequency);
    addLabelled(m_periodic, m_cycles);
    addLabelled(m_periodic, m_settling);

    page(m_sweep);
    m_sweepAmplitude = valueBox(3);
    m_sweepOffset = valueBox(3);
    m_fromHz = valueBox(3);
    m_fromHz->setRange(0.001, 1000);
    m_fromHz->setValue(0.5);
    m_toHz = valueBox(3);
    m_toHz->setRange(0.001, 1000);
    m_toHz->setValue(10);
    m_perDecade = countBox(1, 50, 5);
    m_sweepCycles = countBox(1, 10'000, 3);
    m_sweepSettling = countBox(0, 10'000, 2);
    addLabelled(m_sweep, m_sweepAmplitude);
    addLabelled(m_sweep, m_sweepOffset);
    addLabelled(m_sweep, m_fromHz);
    addLabelled(m_sweep, m_toHz);
    addLabelled(m_sweep, m_perDecade);
    addLabelled(m_sweep, m_sweepCycles);
    addLabelled(m_sweep, m_sweepSettling);

    for (model::SignalKind k : kKinds)
        m_kind->addItem(QString(), static_cast<int>(k));
    for (model::StepDirection d : kDirections)
        m_direction->addItem(QString(), static_cast<int>(d));
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        m_pages->setCurrentIndex(pageOf(kind()));
        emit changed();
    });
    connect(m_direction, &QComboBox::currentIndexChanged, this, &SignalForm::changed);
    setSetValue(QStringLiteral("V"), 3, -10, 10);
    m_from->setValue(3);
    m_to->setValue(5);
    m_amplitude->setValue(1);
    m_offset->setValue(4);
    m_sweepAmplitude->setValue(0.5);
    m_sweepOffset->setValue(4);
    retranslate();
}

NumberBox *SignalForm::valueBox(int decimals)
{
    auto *box = new NumberBox(this);
    box->setDecimals(decimals);
    box->setRange(-1e6, 1e6);
    connect(box, &NumberBox::valueChanged, this, &SignalForm::changed);
    return box;
}

void SignalForm::addLabelled(QFormLayout *form, QWidget *field)
{
    auto *label = new QLabel(this);
    form->addRow(label, field);
    m_labels.push_back(label);
}

WholeNumberBox *SignalForm::countBox(int min, int max, int value)
{
    auto *box = new WholeNumberBox(this);
    box->setRange(min, max);
    box->setValue(value);
    connect(box, &WholeNumberBox::valueChanged, this, &SignalForm::changed);
    return box;
}

void SignalForm::setSetValue(const QString &unit, int decimals, double min, double max)
{
    m_unit = unit;
    const QString suffix = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
    for (NumberBox *box : {m_from, m_to, m_offset, m_sweepOffset}) {
        box->setDecimals(decimals);
        box->setRange(min, max);
        box->setSuffix(suffix);
    }
    for (NumberBox *box : {m_amplitude, m_sweepAmplitude}) {
        box->setDecimals(decimals);
        box->setRange(0, (max - min) / 2);
        box->setSuffix(suffix);
    }
}

model::SignalKind SignalForm::kind() const
{
    return static_cast<model::SignalKind>(m_kind->currentData().toInt());
}

QString SignalForm::kindText() const
{
    return m_kind->currentText();
}

void SignalForm::setKind(model::SignalKind k)
{
    m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(k)));
}

std::optional<model::SignalSpec> SignalForm::spec() const
{
    if (!refusal().isEmpty())
        return std::nullopt;
    model::SignalSpec s;
    s.kind = kind();
    s.from = m_from->value();
    s.to = m_to->value();
    s.hold = m_hold->value();
    s.repeats = m_repeats->value();
    s.direction = static_cast<model::StepDirection>(m_direction->currentData().toInt());
    if (s.kind == model::SignalKind::Sweep) {
        s.amplitude = m_sweepAmplitude->value();
        s.offset = m_sweepOffset->value();
        s.cycles = m_sweepCycles->value();
        s.settlingCycles = m_sweepSettling->value();
    } else {
        s.amplitude = m_amplitude->value();
        s.offset = m_offset->value();
        s.cycles = m_cycles->value();
        s.settlingCycles = m_settling->value();
    }
    s.frequencyHz = m_frequency->value();
    s.fromHz = m_fromHz->value();
    s.toHz = m_toHz->value();
    s.pointsPerDecade = m_perDecade->value();
    return s;
}

QString SignalForm::refusal() const
{
    const int page = pageOf(kind());
    const QFormLayout *form = page == 0 ? m_step : page == 1 ? m_periodic : m_sweep;
    for (int row = 0; row < form->rowCount(); ++row) {
        QLayoutItem *item = form->itemAt(row, QFormLayout::FieldRole);
        if (!item)
            continue;
        if (auto *box = qobject_cast<NumberBox *>(item->widget()); box && !box->number())
            return box->refusal();
        if (auto *box = qobject_cast<WholeNumberBox *>(item->widget()); box && !box->number())
            return box->refusal();
    }
    return {};
}

void SignalForm::setSpec(const model::SignalSpec &s)
{
    setKind(s.kind);
    m_from->setValue(s.from);
    m_to->setValue(s.to);
    m_hold->setValue(s.hold);
    m_repeats->setValue(s.repeats);
    m_direction->setCurrentIndex(m_direction->findData(static_cast<int>(s.direction)));
    NumberBox *amplitude = s.kind == model::SignalKind::Sweep ? m_sweepAmplitude : m_amplitude;
    NumberBox *offset = s.kind == model::SignalKind::Sweep ? m_sweepOffset : m_offset;
    amplitude->setValue(s.amplitude);
    offset->setValue(s.offset);
    m_frequency->setValue(s.frequencyHz);
    m_fromHz->setValue(s.fromHz);
    m_toHz->setValue(s.toHz);
    m_perDecade->setValue(s.pointsPerDecade);
    (s.kind == model::SignalKind::Sweep ? m_sweepCycles : m_cycles)->setValue(s.cycles);
    (s.kind == model::SignalKind::Sweep ? m_sweepSettling : m_settling)->setValue(s.settlingCycles);
}

void SignalForm::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SignalForm::retranslate()
{
    const QStringList kinds = {tr("Step"), tr("Square"), tr("Triangle"), tr("Sine"),
                               tr("Stepped-sine sweep")};
    for (int i = 0; i < m_kind->count(); ++i)
        m_kind->setItemText(i, kinds.value(i));
    const QStringList directions = {tr("up (from → to)"), tr("down (to → from)"),
                                    tr("both (from → to → from)")};
    for (int i = 0; i < m_direction->count(); ++i)
        m_direction->setItemText(i, directions.value(i));
    const QStringList labels = {
        tr("Signal"),
        // step
        tr("From"), tr("To"), tr("Hold (s)"), tr("Repeats"), tr("Direction"),
        // square, triangle, sine
        tr("Amplitude"), tr("Offset"), tr("Frequency (Hz)"), tr("Measured cycles"),
        tr("Settling cycles"),
        // sweep
        tr("Amplitude"), tr("Offset"), tr("From (Hz)"), tr("To (Hz)"), tr("Points per decade"),
        tr("Cycles per point"), tr("Settling cycles")};
    for (std::size_t i = 0; i < m_labels.size(); ++i)
        m_labels[i]->setText(labels.value(static_cast<qsizetype>(i)));
}

} // namespace vt::ui
