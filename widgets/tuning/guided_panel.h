// GuidedPanel: the workbench's "Guided tuning" tab (issue #18 §3) — the person picks a target
// (overshoot at most x %, or fastest without overshoot), the iterations allowed and how many gain
// changes may go without asking, starts a model::GuidedTuning on the workbench's module and step
// (the signal form's From, To and Hold), answers each proposed gain write, and ends with Keep or
// Abort. Each iteration is listed (gains → overshoot, rise and settling time) and handed to the
// workbench as a run, overlaid on its response plot.
// Owner: the WorkbenchView (its tab); GUI thread.
#pragma once

#include "model/tuning/guided_tuning.h"

#include <QWidget>
#include <functional>
#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace vt::ui {

class NumberBox;

// What the panel takes from the workbench around it.
struct GuidedHooks
{
    std::function<model::DeviceAccess *()> access;
    std::function<const model::ModuleInfo *()> module;
    std::function<const dev::ParamMeta *()> setValue;
    std::function<std::optional<model::SignalSpec>()> signal; // the signal form's
    std::function<double()> rateHz;
    std::function<std::optional<double>()> window;
    std::function<bool()> busy; // a workbench test runs
    // A finished iteration for the run list; `overlayPrevious`: tick the run before it.
    std::function<void(std::unique_ptr<model::TuningRun>, bool overlayPrevious)> addRun;
    std::function<void(int module, const std::vector<model::WriteItem> &)> written;
};

class GuidedPanel : public QWidget
{
    Q_OBJECT
public:
    explicit GuidedPanel(GuidedHooks hooks, QWidget *parent = nullptr);
    ~GuidedPanel() override;

    void setTarget(const model::GainTarget &target);
    void setMaxIterations(int n);
    void setAllowance(int n);

    // Start asks once for the step tests; Keep and Abort end the guided change.
    void start();
    void keep();
    void abort();
    // The connection goes: an active change aborts (its restore is tried now) and is dropped.
    void clearConnection();
    bool isActive() const { return m_tuning && m_tuning->isActive(); }
    const model::GuidedTuning *tuning() const { return m_tuning.get(); }
    QString statusText() const { return m_status; }
    QTableWidget *iterationsTable() const { return m_table; }

signals:
    void activeChanged(bool active);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateEnabled();
    void begin(model::GuidedSetup setup);
    void addIteration(int index);
    void offerSourceSwitch();
    void setStatus(const QString &text);

    GuidedHooks m_hooks;
    std::unique_ptr<model::GuidedTuning> m_tuning;
    QString m_status;

    QLabel *m_targetLabel = nullptr;
    QComboBox *m_target = nullptr;
    QLabel *m_overshootLabel = nullptr;
    NumberBox *m_overshoot = nullptr;
    QLabel *m_iterationsLabel = nullptr;
    NumberBox *m_iterations = nullptr;
    QLabel *m_allowLabel = nullptr;
    NumberBox *m_allow = nullptr;
    QLabel *m_stepLabel = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_keep = nullptr;
    QPushButton *m_abort = nullptr;
    QLabel *m_statusLabel = nullptr;
    QTableWidget *m_table = nullptr;
};

} // namespace vt::ui
