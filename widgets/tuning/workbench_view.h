// WorkbenchView: the tuning workbench dock — choose a module, its set value and a signal, start
// a test (model::TestRun) after the person confirmed what it will write, watch the set value and
// the response while it runs, stop it with Stop or Esc, and read the result: the step figures or
// the Bode plot, kept as a run (model::TuningRun) with the module's settings at that time. Runs
// can be overlaid, compared (their setting differences), saved and loaded. Beside the results:
// the guided gain change and the reference fingerprint (workbench_panels.cpp).
// Owner: the main window; GUI thread. The connection's DeviceAccess must outlive the view's use
// of it: clearConnection() before the connection goes.
#pragma once

#include "model/tuning/test_run.h"
#include "model/tuning/tuning_run.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QStackedWidget;
class QTableWidget;
class QTabWidget;

namespace vt::ui {

class BodePlot;
class GuidedPanel;
class ReferencePanel;
class NumberBox;
class ResponsePlot;
class RunList;
class RunResultsTabs;
class SignalForm;

class WorkbenchView : public QWidget
{
    Q_OBJECT
public:
    explicit WorkbenchView(QWidget *parent = nullptr);
    ~WorkbenchView() override;

    void setConnection(model::DeviceAccess *access, const std::vector<model::ModuleInfo> &modules);
    void clearConnection();

    SignalForm *signalForm() const { return m_form; }
    // Chooses module and set value (false when the module has no such set value).
    bool selectTarget(int module, const QString &setValueRow);
    void setRate(double hz);
    void setWindow(std::optional<double> window);

    // Start: checks, asks the person (confirmActuatorWrites), runs. Stop: ends and restores.
    void start();
    void stop();
    bool isRunning() const;

    const std::vector<std::unique_ptr<model::TuningRun>> &runs() const;
    RunList *runList() const { return m_runs; }
    QString statusText() const;
    QTableWidget *resultsTable() const;
    QTableWidget *differencesTable() const;
    GuidedPanel *guidedPanel() const { return m_guided; }
    ReferencePanel *referencePanel() const { return m_reference; }

signals:
    // The set value written back, the source switched and restored: for the monitor's journal.
    void written(int module, const std::vector<vt::model::WriteItem> &items);
    void statusMessage(const QString &text);

protected:
    void changeEvent(QEvent *event) override;

private:
    void build();
    void buildGuided();    // workbench_panels.cpp
    void buildReference(); // workbench_panels.cpp
    bool referenceActive() const;
    void retranslate();
    void moduleChosen();
    void setValueChosen();
    void updateEnabled();
    const model::ModuleInfo *currentModule() const;
    const dev::ParamMeta *currentSetValue() const;
    void begin(model::TestRunSetup setup);
    void onFinished(const model::TestOutcome &outcome);
    void refreshLive();
    void showCurrent();
    QString outcomeText(const model::TestOutcome &outcome) const;

    model::DeviceAccess *m_access = nullptr;
    std::vector<model::ModuleInfo> m_modules; // those with a set value
    std::unique_ptr<model::TestRun> m_test;
    std::unique_ptr<model::TuningRun> m_live; // the run being recorded
    QTimer m_redraw;
    QString m_status;
    std::optional<model::TestOutcome> m_lastOutcome; // of the last finished test

    QLabel *m_moduleLabel = nullptr;
    QComboBox *m_module = nullptr;
    QLabel *m_setValueLabel = nullptr;
    QComboBox *m_setValue = nullptr;
    QLabel *m_responseLabel = nullptr;
    SignalForm *m_form = nullptr;
    QLabel *m_rateLabel = nullptr;
    NumberBox *m_rate = nullptr;
    QCheckBox *m_useWindow = nullptr;
    NumberBox *m_window = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_statusLabel = nullptr;
    QStackedWidget *m_plots = nullptr;
    ResponsePlot *m_response = nullptr;
    BodePlot *m_bode = nullptr;
    RunResultsTabs *m_tabs = nullptr;
    GuidedPanel *m_guided = nullptr;
    ReferencePanel *m_reference = nullptr;
    RunList *m_runs = nullptr;
};

} // namespace vt::ui
