// StepControl: the monitor's set value step — pick a module and its bus set value
// (A1.01 / A2.01), a value in display units, and write it through model::SetValueStep, which
// checks E17 first. A refusal is shown inline with the manuals' reason and an offer to set
// E17 = 2. Both move the valve: each asks the person first (module, parameter, old → new), unless
// the step is armed — once per connection, visibly, disarmed on disconnect. GUI thread.
#pragma once

#include "model/monitor/set_value_step.h"

#include <QWidget>
#include <functional>
#include <memory>
#include <utility>

class QComboBox;
class QLabel;
class QPushButton;

namespace vt::ui {

class NumberBox;

class StepControl : public QWidget
{
    Q_OBJECT
public:
    explicit StepControl(QWidget *parent = nullptr);
    ~StepControl() override;

    void setConnection(model::DeviceAccess *access, const std::vector<model::ModuleInfo> &modules);
    void clearConnection();

    // Chooses the step's target (false when the module has no such writable set value).
    bool selectTarget(int module, const QString &rowName);
    void setStepValue(double display);
    double stepValue() const;

    // The Step button: confirmation (unless armed), E17 check, then the write.
    void writeStep();
    // The offered "Set E17 = 2" button (always confirmed).
    void enableBusSetValue();
    // Arms the step for this connection after one confirmation (false: disarm at once).
    void setArmed(bool armed);
    bool isArmed() const { return m_armed; }

    QString statusText() const;
    bool activationOffered() const; // the "Set E17 = 2" button is shown
    bool isBusy() const;

signals:
    // A write reached its end (the step or E17): for the tuning journal.
    void written(int module, const std::vector<vt::model::WriteItem> &items, bool complete);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    // The activation row and rule the "Set … = …" button writes: the one the last step was
    // refused for, else the module's first.
    std::pair<const dev::ParamMeta *, const dev::SetValueActivation *> activationTarget() const;
    void moduleChosen();
    void rowChosen();
    void updateEnabled();
    const dev::ParamMeta *currentRow() const;
    const model::ModuleInfo *currentModule() const;
    void onWritten(int module, const std::vector<model::WriteItem> &items, bool complete);
    static QString writtenText(const std::vector<model::WriteItem> &items);
    void startStep(const dev::ParamMeta &row, double raw);
    // A typed step the device's resolution cannot hold: the text typed (with unit) and the raw
    // value sent instead; `typed` empty when the value was sent as typed.
    struct Rounding
    {
        QString typed;
        double raw = 0;
    };
    static QString roundingText(const dev::ParamMeta &row, const Rounding &rounding);
    Rounding m_rounding;
    void showArmed();

    model::DeviceAccess *m_access = nullptr;
    std::vector<model::ModuleInfo> m_modules; // those with a bus set value
    std::unique_ptr<model::SetValueStep> m_step;
    QLabel *m_title = nullptr;
    QComboBox *m_module = nullptr;
    QComboBox *m_row = nullptr;
    NumberBox *m_value = nullptr;
    QPushButton *m_write = nullptr;
    QPushButton *m_activate = nullptr;
    QPushButton *m_arm = nullptr;
    bool m_armed = false;
    QLabel *m_status = nullptr;
    // A status made from run-time facts (a write's outcome, the E17 hint) is rendered again in a
    // language switched to while it shows.
    void showStatus(std::function<QString()> render);
    std::function<QString()> m_statusRender;
    QString m_statusShown;
};

} // namespace vt::ui
