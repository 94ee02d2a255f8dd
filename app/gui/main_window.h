// MainWindow: the application shell — menus, the parameter / monitor / telegram docks, the
// status bar with the link state, and the window layout and language kept in AppSettings.
// Features arrive from their own classes; actions whose feature is not built yet stay
// disabled and say so in their status tip. GUI thread only.
#pragma once

#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;

namespace vt::model {
class RecentFiles;
}

namespace vt::app {

class AppSettings;
class Language;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // Does not take ownership of settings or language; both must outlive the window.
    MainWindow(AppSettings &settings, Language &language, QWidget *parent = nullptr);
    ~MainWindow() override;

    QDockWidget *parametersDock() const { return m_parametersDock; }
    QDockWidget *monitorDock() const { return m_monitorDock; }
    QDockWidget *telegramsDock() const { return m_telegramsDock; }
    QLabel *linkStateLabel() const { return m_linkState; }

    // Saves the window layout into the settings (also done on close).
    void saveLayout();

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void retranslate();
    void rebuildRecentMenu();
    void chooseLanguage(const QString &code);
    void showAbout();

    AppSettings &m_settings;
    Language &m_language;
    model::RecentFiles *m_recent = nullptr;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_deviceMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;

    QAction *m_new = nullptr;
    QAction *m_open = nullptr;
    QAction *m_save = nullptr;
    QAction *m_saveAs = nullptr;
    QAction *m_export = nullptr;
    QAction *m_quit = nullptr;
    QAction *m_connect = nullptr;
    QAction *m_disconnect = nullptr;
    QAction *m_readAll = nullptr;
    QAction *m_writeChanges = nullptr;
    QAction *m_scanNode = nullptr;
    QAction *m_foldWizard = nullptr;
    QAction *m_english = nullptr;
    QAction *m_german = nullptr;
    QAction *m_about = nullptr;
    QList<QAction *> m_notYetAvailable;

    QDockWidget *m_parametersDock = nullptr;
    QDockWidget *m_monitorDock = nullptr;
    QDockWidget *m_telegramsDock = nullptr;
    QLabel *m_parametersHint = nullptr;
    QLabel *m_monitorHint = nullptr;
    QLabel *m_telegramsHint = nullptr;
    QLabel *m_welcome = nullptr;
    QLabel *m_linkState = nullptr;
};

} // namespace vt::app
