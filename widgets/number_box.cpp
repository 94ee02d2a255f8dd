#include "number_box.h"

#include "model/text_language.h"

#include <QEvent>
#include <QFocusEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QToolTip>
#include <cmath>

namespace vt::ui {
namespace {

// The number in a spin box's text, without its prefix and suffix.
QString numberPart(QString text, const QString &prefix, const QString &suffix)
{
    if (!prefix.isEmpty() && text.startsWith(prefix))
        text.remove(0, prefix.size());
    if (!suffix.isEmpty() && text.endsWith(suffix))
        text.chop(suffix.size());
    else if (!suffix.trimmed().isEmpty() && text.trimmed().endsWith(suffix.trimmed()))
        text = text.trimmed().chopped(suffix.trimmed().size());
    return text.trimmed();
}

model::NumberParse parseBoxText(const QAbstractSpinBox &box, const QString &text,
                                const QString &prefix, const QString &suffix,
                                const model::NumberRules &rules)
{
    if (!box.specialValueText().isEmpty() && text.trimmed() == box.specialValueText().trimmed())
        return {rules.minimum, QString()}; // Qt shows the special text for the minimum
    return model::parseNumber(numberPart(text, prefix, suffix), model::textLanguage(), rules);
}

bool isCommitKey(const QKeyEvent *event)
{
    return event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
}

// The refusal is said where the person looks (a tool tip at the box) and to the owner, which
// shows it in its status line; the typed text stays so it can be corrected.
template<typename Box> void refuse(Box *box, const QString &reason, bool show)
{
    if (!show)
        return;
    QToolTip::showText(box->mapToGlobal(QPoint(0, box->height())), reason, box);
    emit box->refused(reason);
}

} // namespace

NumberBox::NumberBox(QWidget *parent) : QDoubleSpinBox(parent)
{
    // Typing "1,5" in English passes through "1", a number: with tracking, the box would take 1.
    setKeyboardTracking(false);
}

model::NumberParse NumberBox::parse(const QString &text) const
{
    model::NumberRules rules;
    rules.decimals = decimals();
    rules.minimum = minimum();
    rules.maximum = maximum();
    rules.unit = suffix().trimmed();
    return parseBoxText(*this, text, prefix(), suffix(), rules);
}

std::optional<double> NumberBox::number() const
{
    return parse(text()).value;
}

QString NumberBox::refusal() const
{
    return parse(text()).refusal;
}

QValidator::State NumberBox::validate(QString &input, int &pos) const
{
    Q_UNUSED(pos)
    // Anything may be typed; what does not parse is refused with a reason on Enter or when the
    // box loses focus, instead of being blocked key by key or replaced silently.
    return parse(input).ok() ? QValidator::Acceptable : QValidator::Intermediate;
}

double NumberBox::valueFromText(const QString &text) const
{
    return parse(text).value.value_or(value());
}

QString NumberBox::textFromValue(double value) const
{
    return model::formatNumber(value, decimals(), model::textLanguage());
}

void NumberBox::fixup(QString &input) const
{
    Q_UNUSED(input) // never corrected into another value
}

void NumberBox::keyPressEvent(QKeyEvent *event)
{
    if (isCommitKey(event) && !number()) {
        refuse(this, refusal(), true);
        event->accept();
        return;
    }
    QDoubleSpinBox::keyPressEvent(event);
}

void NumberBox::focusOutEvent(QFocusEvent *event)
{
    if (number()) {
        QDoubleSpinBox::focusOutEvent(event);
        return;
    }
    // QAbstractSpinBox would put the previous value back without a word.
    refuse(this, refusal(),
           event->reason() != Qt::PopupFocusReason &&
               event->reason() != Qt::ActiveWindowFocusReason);
    lineEdit()->event(event);
    QWidget::focusOutEvent(event);
}

void NumberBox::changeEvent(QEvent *event)
{
    QDoubleSpinBox::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        setSuffix(suffix()); // shows the value again, in the new language's notation
}

WholeNumberBox::WholeNumberBox(QWidget *parent) : QSpinBox(parent)
{
    setKeyboardTracking(false);
}

model::NumberParse WholeNumberBox::parse(const QString &text) const
{
    model::NumberRules rules;
    rules.decimals = 0;
    rules.minimum = minimum();
    rules.maximum = maximum();
    rules.unit = suffix().trimmed();
    return parseBoxText(*this, text, prefix(), suffix(), rules);
}

std::optional<int> WholeNumberBox::number() const
{
    const model::NumberParse parsed = parse(text());
    if (!parsed.value)
        return std::nullopt;
    return static_cast<int>(std::lround(*parsed.value));
}

QString WholeNumberBox::refusal() const
{
    return parse(text()).refusal;
}

QValidator::State WholeNumberBox::validate(QString &input, int &pos) const
{
    Q_UNUSED(pos)
    return parse(input).ok() ? QValidator::Acceptable : QValidator::Intermediate;
}

int WholeNumberBox::valueFromText(const QString &text) const
{
    const model::NumberParse parsed = parse(text);
    return parsed.value ? static_cast<int>(std::lround(*parsed.value)) : value();
}

QString WholeNumberBox::textFromValue(int value) const
{
    return model::formatNumber(value, 0, model::textLanguage());
}

void WholeNumberBox::fixup(QString &input) const
{
    Q_UNUSED(input)
}

void WholeNumberBox::keyPressEvent(QKeyEvent *event)
{
    if (isCommitKey(event) && !number()) {
        refuse(this, refusal(), true);
        event->accept();
        return;
    }
    QSpinBox::keyPressEvent(event);
}

void WholeNumberBox::focusOutEvent(QFocusEvent *event)
{
    if (number()) {
        QSpinBox::focusOutEvent(event);
        return;
    }
    refuse(this, refusal(),
           event->reason() != Qt::PopupFocusReason &&
               event->reason() != Qt::ActiveWindowFocusReason);
    lineEdit()->event(event);
    QWidget::focusOutEvent(event);
}

void WholeNumberBox::changeEvent(QEvent *event)
{
    QSpinBox::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        setSuffix(suffix());
}

} // namespace vt::ui
