// SignalForm: the workbench's signal choice and its parameters — step (from, to, hold, repeats,
// direction), square / triangle / sine (amplitude, offset, frequency, cycles, settling cycles)
// and the stepped-sine sweep (amplitude, offset, from/to frequency, points per decade, cycles,
// settling cycles) — in the set value's unit and the UI language's notation (NumberBox).
// GUI thread; owned by the workbench view.
#pragma once

#include "model/tuning/test_signal.h"

#include <QWidget>
#include <optional>
#include <vector>

class QComboBox;
class QFormLayout;
class QLabel;
class QStackedWidget;

namespace vt::ui {

class NumberBox;
class WholeNumberBox;

class SignalForm : public QWidget
{
    Q_OBJECT
public:
    explicit SignalForm(QWidget *parent = nullptr);

    // The set value's unit and display decimals, and its limits (display units).
    void setSetValue(const QString &unit, int decimals, double min, double max);

    model::SignalKind kind() const;
    QString kindText() const; // the signal's name as the combo box shows it
    void setKind(model::SignalKind kind);
    // The spec as typed; empty while a box holds text that is not a number (refusal() says which).
    std::optional<model::SignalSpec> spec() const;
    QString refusal() const;
    // Fills the boxes from `spec` (its kind included).
    void setSpec(const model::SignalSpec &spec);

signals:
    void changed();

protected:
    void changeEvent(QEvent *event) override;

private:
    NumberBox *valueBox(int decimals);
    WholeNumberBox *countBox(int min, int max, int value);
    void addLabelled(QFormLayout *form, QWidget *field); // labels in retranslate()'s order
    void retranslate();

    QComboBox *m_kind = nullptr;
    QStackedWidget *m_pages = nullptr;
    QFormLayout *m_step = nullptr;
    QFormLayout *m_periodic = nullptr;
    QFormLayout *m_sweep = nullptr;
    NumberBox *m_from = nullptr;
    NumberBox *m_to = nullptr;
    NumberBox *m_hold = nullptr;
    WholeNumberBox *m_repeats = nullptr;
    QComboBox *m_direction = nullptr;
    NumberBox *m_amplitude = nullptr;
    NumberBox *m_offset = nullptr;
    NumberBox *m_frequency = nullptr;
    WholeNumberBox *m_cycles = nullptr;
    WholeNumberBox *m_settling = nullptr;
    NumberBox *m_sweepAmplitude = nullptr;
    NumberBox *m_sweepOffset = nullptr;
    NumberBox *m_fromHz = nullptr;
    NumberBox *m_toHz = nullptr;
    WholeNumberBox *m_perDecade = nullptr;
    WholeNumberBox *m_sweepCycles = nullptr;
    WholeNumberBox *m_sweepSettling = nullptr;
    QString m_unit;
    std::vector<QLabel *> m_labels;
};

} // namespace vt::ui
