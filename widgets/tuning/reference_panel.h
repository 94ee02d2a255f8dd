// ReferencePanel: the workbench's "Reference" tab (issue #19, docs/TUNING.md "Reference
// fingerprint") — Save as Reference… runs the standard test set (steps up and down between
// centre − amplitude and centre + amplitude, optionally a stepped-sine sweep) on the workbench's
// module and set value and writes the settings and the runs into one .vtref file; Compare with
// Reference… reads such a file, checks it fits the module (family, mode; says why not), repeats
// its tests with the same specs and shows the drift against the editable thresholds
// (ReferenceDriftView). The person confirms once for the whole set; a set-value source that differs
// is asked for separately, as for any workbench test.
// Owner: the WorkbenchView (its tab); GUI thread.
#pragma once

#include "model/tuning/reference_session.h"

#include <QWidget>
#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QLabel;
class QPushButton;

namespace vt::ui {

class NumberBox;
class ReferenceDriftView;

// What the panel takes from the workbench around it.
struct ReferenceHooks
{
    std::function<model::DeviceAccess *()> access;
    std::function<const model::ModuleInfo *()> module; // the workbench's choice
    std::function<const model::ModuleInfo *(int address)> moduleAt;
    std::function<const dev::ParamMeta *()> setValue;
    std::function<double()> rateHz;
    std::function<std::optional<double>()> window;
    std::function<bool()> busy; // another test runs
    std::function<void(int module, const std::vector<model::WriteItem> &)> written;
};

class ReferencePanel : public QWidget
{
    Q_OBJECT
public:
    explicit ReferencePanel(ReferenceHooks hooks, QWidget *parent = nullptr);
    ~ReferencePanel() override;

    // The set value's unit and range (the workbench's choice changed): the plan's boxes follow.
    void setSetValue(const QString &unit, int decimals, double min, double max);
    void setPlan(const model::ReferencePlan &plan);
    model::ReferencePlan plan() const;
    void setThresholds(const model::DriftThresholds &thresholds);
    model::DriftThresholds thresholds() const;

    // Ask, run the set, write `path` (Save) / read `path`, ask, run, compare (Compare).
    void saveAs(const QString &path);
    void compareWith(const QString &path);
    void stop();
    // The connection goes: a running set stops (its restore is tried now) and is dropped.
    void clearConnection();
    bool isActive() const { return m_session && m_session->isActive(); }
    QString statusText() const { return m_status; }
    const std::optional<model::ReferenceComparison> &comparison() const { return m_comparison; }
    // The reference saved or loaded last and its file (what comparison() compared with).
    const std::optional<model::Reference> &reference() const { return m_reference; }
    const QString &referencePath() const { return m_path; }
    ReferenceDriftView *driftView() const { return m_view; }
    // The workbench's module, set value or connection changed.
    void updateEnabled();

signals:
    void activeChanged(bool active);

protected:
    void changeEvent(QEvent *event) override;

private:
    enum class Purpose { Save, Compare };
    void retranslate();
    void setStatus(const QString &text);
    // A status said again in the new language when the language changes.
    void setStatus(std::function<QString()> text);
    void ask(const model::ReferenceSetup &setup, Purpose purpose);
    void run(model::ReferenceSetup setup, Purpose purpose);
    void onFinished(bool complete);
    void recompute();

    ReferenceHooks m_hooks;
    std::unique_ptr<model::ReferenceSession> m_session;
    Purpose m_purpose = Purpose::Save;
    QString m_path;
    model::ReferencePlan m_runningPlan;
    std::optional<model::Reference> m_reference; // saved or loaded
    std::vector<std::shared_ptr<model::TuningRun>> m_now;
    std::vector<model::RunSetting> m_nowSettings;
    std::optional<model::ReferenceComparison> m_comparison;
    QString m_status;
    std::function<QString()> m_statusText; // when the status follows the language

    QLabel *m_centreLabel = nullptr;
    NumberBox *m_centre = nullptr;
    QLabel *m_amplitudeLabel = nullptr;
    NumberBox *m_amplitude = nullptr;
    QLabel *m_holdLabel = nullptr;
    NumberBox *m_hold = nullptr;
    QCheckBox *m_sweep = nullptr;
    QLabel *m_fromLabel = nullptr;
    NumberBox *m_fromHz = nullptr;
    QLabel *m_toLabel = nullptr;
    NumberBox *m_toHz = nullptr;
    QLabel *m_thresholdsLabel = nullptr;
    QLabel *m_riseLabel = nullptr;
    NumberBox *m_rise = nullptr;
    QLabel *m_overshootLabel = nullptr;
    NumberBox *m_overshoot = nullptr;
    QLabel *m_settlingLabel = nullptr;
    NumberBox *m_settling = nullptr;
    QLabel *m_errorLabel = nullptr;
    NumberBox *m_error = nullptr;
    QLabel *m_bandwidthLabel = nullptr;
    NumberBox *m_bandwidth = nullptr;
    QLabel *m_phaseLabel = nullptr;
    NumberBox *m_phase = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_compare = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_statusLabel = nullptr;
    ReferenceDriftView *m_view = nullptr;
};

} // namespace vt::ui
