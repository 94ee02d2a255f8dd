// InspectorView: the telegram inspector — the live list of every frame in and out with
// filters, pause, clear and save; the selected frame's field tree and hex view; a decode box for
// pasted frames and a composer that sends on the current link; linked navigation between frames
// and parameters. Owner: the main window; GUI thread only. The log and the connection are not
// owned (the log must outlive the view or be replaced with setLog(nullptr) first).
#pragma once

#include "inspect/frame_parameters.h"
#include "model/session/device_access.h"
#include "model/telegrams/telegram_log.h"

#include <QPointer>
#include <QWidget>
#include <map>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QMenu;
class QPushButton;
class QTabWidget;
class QTableView;

namespace vt::model {
class Connection;
class TelegramLogModel;
} // namespace vt::model

namespace vt::ui {

class ComposePanel;
class DecodePanel;
class FrameDetail;

class InspectorView : public QWidget
{
    Q_OBJECT
public:
    explicit InspectorView(QWidget *parent = nullptr);
    ~InspectorView() override;

    void setLog(vt::model::TelegramLog *log);
    vt::model::TelegramLog *log() const { return m_log; }
    // The modules name parameters (their dictionaries) and fill the module filter; the
    // connection is where the composer sends.
    void setConnection(vt::model::Connection *connection,
                       const std::vector<vt::model::ModuleInfo> &modules);
    void clearConnection();

    // Selects the newest exchange that carried the parameter (request and its answers), lifting
    // filters that hide it. Nothing is selected when no such frame is in the log.
    void showFramesFor(int module, const QString &parameterName);

    void setFilter(const vt::model::TelegramFilter &filter);
    vt::model::TelegramFilter filter() const;
    QList<quint64> selectedSeqs() const;
    // The parameters the current frame's exchange addresses (first = the one "Go to" opens).
    QStringList parametersOfCurrent() const;

    bool saveCsv(const QString &path, QString *error = nullptr) const;
    bool saveText(const QString &path, QString *error = nullptr) const;

    QTableView *table() const { return m_table; }
    vt::model::TelegramLogModel *logModel() const { return m_model; }
    FrameDetail *frameDetail() const { return m_detail; }
    DecodePanel *decodePanel() const { return m_decode; }
    ComposePanel *composePanel() const { return m_compose; }

signals:
    // The user asked to jump from a frame to its parameter.
    void parameterActivated(int module, const QString &parameterName);

public slots:
    // Emits parameterActivated() for the current frame's first parameter; false when it has none.
    bool activateParameterOfCurrent();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void rebuildModuleFilter();
    void applyFilterFromControls();
    void syncControlsToFilter(const vt::model::TelegramFilter &filter);
    void onCurrentRowChanged();
    void onRowsInserted();
    void onContextMenu(const QPoint &pos);
    void saveInteractive(bool csv);
    vt::model::SummaryOptions summaryOptions() const;
    // The connection's ED1 image layout (IND byte, PZD words, gateway register bytes).
    vt::dev::inspect::ImageLayout imageLayout() const;
    const vt::dev::Dictionary *dictionaryFor(int module) const;
    vt::dev::hcs::Family familyFor(int module) const;

    QPointer<vt::model::TelegramLog> m_log;
    vt::model::TelegramLogModel *m_model = nullptr;
    QPointer<vt::model::Connection> m_connection;
    std::vector<vt::model::ModuleInfo> m_modules;

    QLabel *m_moduleLabel;
    QComboBox *m_moduleFilter;
    QLabel *m_protocolLabel;
    QComboBox *m_protocolFilter;
    QCheckBox *m_errorsOnly;
    QPushButton *m_pause;
    QPushButton *m_clear;
    QPushButton *m_saveCsv;
    QPushButton *m_saveText;
    QPushButton *m_goTo;
    QTableView *m_table;
    QTabWidget *m_tabs;
    FrameDetail *m_detail;
    DecodePanel *m_decode;
    ComposePanel *m_compose;
    bool m_syncing = false;
};

} // namespace vt::ui
