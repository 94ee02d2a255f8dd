// MainWindow: the application shell — menus, the parameter editor in the centre, the node,
// monitor, telegram and linearisation docks, the status bar with the link state, and the window
// layout and language kept in AppSettings. The work itself is done by the Workspace (document,
// connection, telegram log) and the File/Device controllers. GUI thread only.
#pragma once

#include "model/session/connection.h"

#include <QMainWindow>
#include <QPointer>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QStackedWidget;

namespace vt::dev {
class DictionarySet;
}

namespace vt::model {
class CurveBinding;
class LCurveTableModel;
class RecentFiles;
} // namespace vt::model

namespace vt::ui {
class FoldWizard;
class InspectorView;
class MonitorView;
class LinkStatusWidget;
class LCurveEditor;
class NodeView;
class ParameterEditor;
class WorkbenchView;
} // namespace vt::ui

namespace vt::app {

class AppSettings;
class DeviceController;
class FileController;
class Language;
class QuitController;
class ReportController;
class WelcomePage;
class Workspace;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // Does not take ownership of settings or language; both must outlive the window.
    MainWindow(AppSettings &settings, Language &language, QWidget *parent = nullptr);
    ~MainWindow() override;

    Workspace &workspace() const { return *m_workspace; }
    FileController &files() const { return *m_files; }
    DeviceController &device() const { return *m_device; }
    // The one question before the window closes, and what follows the answer.
    QuitController &quitController() const { return *m_quitController; }
    ui::ParameterEditor *editor() const { return m_editor; }
    WelcomePage *welcomePage() const { return m_welcome; }
    QDockWidget *nodeDock() const { return m_nodeDock; }
    QDockWidget *monitorDock() const { return m_monitorDock; }
    QDockWidget *workbenchDock() const { return m_workbenchDock; }
    ui::WorkbenchView *workbench() const { return m_workbench; }
    QDockWidget *telegramsDock() const { return m_telegramsDock; }
    QDockWidget *curveDock() const { return m_curveDock; }
    ui::LCurveEditor *curveEditor() const { return m_curveEditor; }
    ui::InspectorView *inspector() const { return m_inspector; }
    ui::MonitorView *monitor() const { return m_monitor; }
    ui::NodeView *nodeView() const { return m_nodeView; }
    ui::LinkStatusWidget *linkStatus() const { return m_linkStatus; }

    // Device ▸ Fold Wizard; with a path, the wizard opens on that saved fold plan (.vtfold).
    ui::FoldWizard *openFoldWizard(const QString &planPath = {});

    // Saves the window layout into the settings (also done on close).
    void saveLayout();

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void connectWorkspace();
    void retranslate();
    void updateUndoActions();
    void rebuildRecentMenu();
    void chooseLanguage(const QString &code);
    void applyDocumentLanguage();
    void updateActions();
    void updateTitle();
    void showStatus(const QString &text);
    void showAbout();
    void openSessionLogFolder(); // where the session log (model/audit) keeps every write

    AppSettings &m_settings;
    Language &m_language;
    Workspace *m_workspace = nullptr;
    FileController *m_files = nullptr;
    DeviceController *m_device = nullptr;
    QuitController *m_quitController = nullptr;
    model::RecentFiles *m_recent = nullptr;
    ui::ParameterEditor *m_editor = nullptr;
    WelcomePage *m_welcome = nullptr;
    QStackedWidget *m_centre = nullptr; // the welcome page or the editor
    ui::NodeView *m_nodeView = nullptr;
    model::LCurveTableModel *m_curves = nullptr;
    model::CurveBinding *m_curveBinding = nullptr;
    ui::LCurveEditor *m_curveEditor = nullptr;
    ui::InspectorView *m_inspector = nullptr;
    ui::MonitorView *m_monitor = nullptr;
    QPointer<ui::FoldWizard> m_wizard;
    bool m_viewLayoutRestored = false;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_deviceMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;

    QAction *m_new = nullptr;
    QAction *m_open = nullptr;
    QAction *m_save = nullptr;
    QAction *m_saveAs = nullptr;
    QAction *m_export = nullptr;
    QAction *m_reportAction = nullptr;
    QAction *m_compareFile = nullptr;
    QAction *m_sessionLogs = nullptr;
    QAction *m_quit = nullptr;
    QAction *m_undo = nullptr;
    QAction *m_redo = nullptr;
    QAction *m_revertDevice = nullptr;
    QAction *m_revertFile = nullptr;
    QAction *m_connect = nullptr;
    QAction *m_disconnect = nullptr;
    QAction *m_readAll = nullptr;
    QAction *m_writeChanges = nullptr;
    QAction *m_compareDevice = nullptr;
    QAction *m_scanNode = nullptr;
    QAction *m_foldWizard = nullptr;
    QAction *m_liveValues = nullptr;
    QAction *m_english = nullptr;
    QAction *m_german = nullptr;
    QAction *m_about = nullptr;
    QAction *m_guide = nullptr;

    QDockWidget *m_nodeDock = nullptr;
    QDockWidget *m_monitorDock = nullptr;
    QDockWidget *m_workbenchDock = nullptr;
    ui::WorkbenchView *m_workbench = nullptr;
    ReportController *m_report = nullptr;
    QDockWidget *m_telegramsDock = nullptr;
    QDockWidget *m_curveDock = nullptr;
    ui::LinkStatusWidget *m_linkStatus = nullptr;
};

} // namespace vt::app
