// Numeric inputs that parse and show numbers in the UI language of the moment
// (model/number_text.h), also after a run-time language switch: a QWidget's own locale() is a copy
// of the default taken when the widget was made, so a stock spin box made in English goes on
// reading "1,5" as 15 or falls back to its previous value after a switch to German. These boxes
// read the language at every keystroke, re-render their value on LanguageChange, and refuse an
// entry that is not exactly a number: the text stays as typed, value() keeps the last accepted
// value, number() is empty, and refused() carries the sentence naming the expected notation. GUI
// thread only; owned by their parent widget.
#pragma once

#include "model/number_text.h"

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <optional>

namespace vt::ui {

// A decimal number with decimals() digits after the decimal sign.
class NumberBox : public QDoubleSpinBox
{
    Q_OBJECT
public:
    explicit NumberBox(QWidget *parent = nullptr);

    // The number the text shows now, or nothing while it is refused (then refusal() says why).
    std::optional<double> number() const;
    QString refusal() const;

signals:
    void refused(const QString &reason);

protected:
    QValidator::State validate(QString &input, int &pos) const override;
    double valueFromText(const QString &text) const override;
    QString textFromValue(double value) const override;
    void fixup(QString &input) const override;
    void keyPressEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    model::NumberParse parse(const QString &text) const;
};

// A whole number (ports, addresses, counts, intervals).
class WholeNumberBox : public QSpinBox
{
    Q_OBJECT
public:
    explicit WholeNumberBox(QWidget *parent = nullptr);

    std::optional<int> number() const;
    QString refusal() const;

signals:
    void refused(const QString &reason);

protected:
    QValidator::State validate(QString &input, int &pos) const override;
    int valueFromText(const QString &text) const override;
    QString textFromValue(int value) const override;
    void fixup(QString &input) const override;
    void keyPressEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    model::NumberParse parse(const QString &text) const;
};

} // namespace vt::ui
