// MonitorView: the live monitor dock — polls chosen d-values of the connected modules
// into bounded stores (model::MonitorSession) and plots them with coalesced redraws (≤ 25/s,
// only while visible), rate and window controls, pause, zoom/pan, a cursor read-out, the tuning
// journal's write markers, a set value step, and CSV / PNG / PDF export. GUI thread.
#pragma once

#include "model/monitor/monitor_session.h"
#include "model/session/write_record.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QPushButton;
class QToolButton;
class QAction;

namespace vt::ui {

class NumberBox;

class MonitorPlot;
class StepControl;

class MonitorView : public QWidget
{
    Q_OBJECT
public:
    // Redraws are at least this far apart (≤ 25 per second, STYLE.md rule 10).
    static constexpr int kMinRedrawMs = 40;

    explicit MonitorView(QWidget *parent = nullptr);
    ~MonitorView() override;

    // `modules` identified, each with its dictionary; `c` must stay alive until clearConnection().
    // Shows the default channels of the first module; polling starts with start() (the Start
    // button), not here.
    void setConnection(model::Connection *c, std::vector<model::ModuleInfo> modules);
    // Stops polling and drops the scheduler (call before the connection goes); the recording stays
    // for viewing and export.
    void clearConnection();

    // The tuning journal: marks the items of a finished parameter write that reached the device
    // ("C1.07 0.800 V → 1.000 V") at the current time.
    void journalWrites(int module, const std::vector<model::WriteItem> &items);

    void start();
    void pause();
    bool isRunning() const { return m_session->isRunning(); }
    void setRate(double hz); // 0: as fast as the link allows
    void setWindowSeconds(double seconds);
    double windowSeconds() const;
    // The time axis follows the newest sample (off after the user pans or zooms).
    void setFollowing(bool on);
    bool isFollowing() const;

    // `visibleOnly`: the time axis' current range, else everything recorded.
    bool exportCsv(const QString &path, bool visibleOnly, QString *error = nullptr);
    bool exportPng(const QString &path);
    bool exportPdf(const QString &path);

    // Opens the channel chooser (modal).
    void chooseChannels();
    // Applies a selection without the dialog (module -> rows; modules left out stop being polled).
    void setChannels(const std::map<int, std::vector<const dev::ParamMeta *>> &selection);

    model::MonitorSession &session() const { return *m_session; }
    MonitorPlot *plot() const { return m_plot; }
    StepControl *stepControl() const { return m_step; }
    QString achievedRateText() const;
    QString readoutText() const;
    int replotCount() const;

signals:
    // For the main window's status bar: a failed poll, an export done.
    void statusMessage(const QString &text);
    // The person stopped the monitor (its Stop button): the end of a test, when set values the
    // tool changed are offered back.
    void stoppedByUser();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void retranslate();
    void scheduleRedraw();
    void redraw();
    void rebuildPlotChannels();
    void updateControls();
    void updateRateLabel();
    void showReadout(double t);
    void onRangeChanged();
    void exportWithDialog(int kind);

    model::MonitorSession *m_session = nullptr;
    MonitorPlot *m_plot = nullptr;
    StepControl *m_step = nullptr;
    QPushButton *m_run = nullptr;
    QLabel *m_rateLabel = nullptr;
    NumberBox *m_rate = nullptr;
    QLabel *m_achieved = nullptr;
    QLabel *m_windowLabel = nullptr;
    NumberBox *m_window = nullptr;
    QCheckBox *m_follow = nullptr;
    QPushButton *m_channels = nullptr;
    QPushButton *m_clear = nullptr;
    QToolButton *m_export = nullptr;
    QAction *m_exportVisible = nullptr;
    QAction *m_exportAll = nullptr;
    QAction *m_exportPng = nullptr;
    QAction *m_exportPdf = nullptr;
    QLabel *m_readout = nullptr;
    QTimer m_redraw;
    QString m_lastFailure;
    QElapsedTimer m_sinceFailure;
    bool m_dirty = false;
    bool m_applyingRange = false;
};

} // namespace vt::ui
