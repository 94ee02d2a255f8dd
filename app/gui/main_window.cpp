#include "main_window.h"

#include "app_settings.h"
#include "device_controller.h"
#include "device_state_control.h"
#include "dict/dictionary_loader.h"
#include "file_controller.h"
#include "language.h"
#include "layout_memory.h"
#include "model/audit/audit_log.h"
#include "model/curve/lcurve_table_model.h"
#include "model/params/curve_binding.h"
#include "model/recent_files.h"
#include "quit_controller.h"
#include "report_controller.h"
#include "transports/link.h"
#include "welcome_page.h"
#include "widgets/about_dialog.h"
#include "widgets/connect/link_status_widget.h"
#include "widgets/curve/lcurve_editor.h"
#include "widgets/editor/node_view.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/fold/fold_apply_page.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/tuning/workbench_view.h"
#include "widgets/user_guide_dialog.h"
#include "workspace.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>

namespace vt::app {

MainWindow::MainWindow(AppSettings &settings, Language &language, QWidget *parent)
    : QMainWindow(parent), m_settings(settings), m_language(language)
{
    setObjectName(QStringLiteral("MainWindow"));
    m_workspace = new Workspace(*dev::builtinDictionaries(), this);
    m_recent = new model::RecentFiles(model::RecentFiles::kDefaultLimit, this);
    m_recent->setFiles(m_settings.recentFiles());
    m_files = new FileController(*m_workspace, *m_recent, this);
    m_device = new DeviceController(*m_workspace, m_settings, this);

    // The editor, or while there is neither a device nor a file, the ways to start.
    m_editor = new ui::ParameterEditor(m_workspace->document(), this);
    m_welcome = new WelcomePage(this);
    m_centre = new QStackedWidget(this);
    m_centre->addWidget(m_welcome);
    m_centre->addWidget(m_editor);
    setCentralWidget(m_centre);
    createActions();
    createMenus();
    createDocks();
    m_report = new ReportController(*m_workspace, m_language, *m_workbench, this);
    connect(m_reportAction, &QAction::triggered, this, [this] { m_report->openDialog(this); });
    m_quitController = new QuitController(*m_workspace, *m_files, *m_device, m_workbench,
                                          m_monitor->stepControl(), this);
    connect(m_quitController, &QuitController::statusMessage, this, &MainWindow::showStatus);

    // Link, device identity and the error / retry counters, live.
    m_linkStatus = new ui::LinkStatusWidget(this);
    m_linkStatus->setObjectName(QStringLiteral("linkStatus"));
    statusBar()->addPermanentWidget(m_linkStatus);

    connect(m_recent, &model::RecentFiles::changed, this, &MainWindow::rebuildRecentMenu);
    connect(&m_language, &Language::languageChanged, this, [this](const QString &code) {
        m_english->setChecked(code == QLatin1String("en"));
        m_german->setChecked(code == QLatin1String("de"));
        applyDocumentLanguage();
        updateUndoActions();
        // A passing status message stays in the language it was said in: it goes.
        statusBar()->clearMessage();
        // Texts made from run-time facts, not from a tr() of their own widget.
        if (m_workspace->connection() && !m_workspace->modules().empty())
            m_nodeView->setNodeText(m_workspace->connection()->displayText());
    });
    m_english->setChecked(m_language.current() != QLatin1String("de"));
    m_german->setChecked(m_language.current() == QLatin1String("de"));
    applyDocumentLanguage();
    connectWorkspace();

    // Fits a 1366 × 768 laptop (the window manager maximises a larger default there).
    resize(1340, 720);
    restoreGeometry(m_settings.windowGeometry());
    restoreState(m_settings.windowState());
    retranslate();
    updateActions();
}

MainWindow::~MainWindow()
{
    // Close the connection while every window that holds it (monitor, inspector, wizard) still
    // exists.
    m_workspace->disconnectFromDevice();
    // The workspace outlives this part of the window (it is a child): its document's undo stack
    // still signals while it is destroyed, so nothing of it may reach this window any more.
    QObject::disconnect(m_workspace->document().undoStack(), nullptr, this, nullptr);
    QObject::disconnect(&m_workspace->document(), nullptr, this, nullptr);
    QObject::disconnect(m_workspace, nullptr, this, nullptr);
}

void MainWindow::createActions()
{
    auto make = [this](const char *name, QKeySequence::StandardKey key = QKeySequence::UnknownKey) {
        auto *a = new QAction(this);
        a->setObjectName(QString::fromLatin1(name));
        if (key != QKeySequence::UnknownKey)
            a->setShortcut(key);
        return a;
    };
    m_new = make("actionNew", QKeySequence::New);
    m_open = make("actionOpen", QKeySequence::Open);
    m_save = make("actionSave", QKeySequence::Save);
    m_saveAs = make("actionSaveAs", QKeySequence::SaveAs);
    m_export = make("actionExport");
    m_reportAction = make("actionReport");
    m_compareFile = make("actionCompareFile");
    m_sessionLogs = make("actionSessionLogFolder");
    m_quit = make("actionQuit", QKeySequence::Quit);
    // Not QUndoStack::createUndoAction(): its "Undo %1" is fixed in the language the action was
    // made in, and a run-time switch has to re-render it (updateUndoActions).
    QUndoStack *undo = m_workspace->document().undoStack();
    m_undo = make("actionUndo", QKeySequence::Undo);
    m_redo = make("actionRedo", QKeySequence::Redo);
    connect(m_undo, &QAction::triggered, undo, &QUndoStack::undo);
    connect(m_redo, &QAction::triggered, undo, &QUndoStack::redo);
    for (auto changed : {&QUndoStack::canUndoChanged, &QUndoStack::canRedoChanged})
        connect(undo, changed, this, &MainWindow::updateUndoActions);
    for (auto changed : {&QUndoStack::undoTextChanged, &QUndoStack::redoTextChanged})
        connect(undo, changed, this, &MainWindow::updateUndoActions);
    m_revertDevice = make("actionRevertDevice");
    m_revertFile = make("actionRevertFile");
    m_connect = make("actionConnect");
    m_disconnect = make("actionDisconnect");
    m_readAll = make("actionReadAll");
    m_writeChanges = make("actionWriteChanges");
    m_compareDevice = make("actionCompareDevice");
    m_scanNode = make("actionScanNode");
    m_foldWizard = make("actionFoldWizard");
    m_liveValues = make("actionLiveValues");
    m_liveValues->setCheckable(true);
    m_liveValues->setChecked(true);
    m_about = make("actionAbout");
    m_guide = make("actionUserGuide");
    m_english = make("actionEnglish");
    m_german = make("actionGerman");

    auto *group = new QActionGroup(this);
    for (QAction *a : {m_english, m_german}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    connect(m_english, &QAction::triggered, this, [this] { chooseLanguage(QStringLiteral("en")); });
    connect(m_german, &QAction::triggered, this, [this] { chooseLanguage(QStringLiteral("de")); });
    connect(m_quit, &QAction::triggered, this, &QWidget::close);
    connect(m_about, &QAction::triggered, this, &MainWindow::showAbout);
    connect(m_sessionLogs, &QAction::triggered, this, &MainWindow::openSessionLogFolder);
    connect(m_guide, &QAction::triggered, this, [this] {
        auto *guide = findChild<ui::UserGuideDialog *>();
        if (!guide) {
            guide = new ui::UserGuideDialog(this);
            guide->setAttribute(Qt::WA_DeleteOnClose);
        }
        guide->show();
        guide->raise();
    });
    connect(m_new, &QAction::triggered, m_files, &FileController::newFile);
    connect(m_open, &QAction::triggered, m_files, &FileController::open);
    connect(m_save, &QAction::triggered, m_files, &FileController::save);
    connect(m_saveAs, &QAction::triggered, m_files, &FileController::saveAs);
    connect(m_export, &QAction::triggered, m_files, &FileController::exportCsv);
    connect(m_compareFile, &QAction::triggered, m_files, &FileController::compareWithFile);
    connect(m_revertDevice, &QAction::triggered, this,
            [this] { m_workspace->document().revertToDevice(); });
    connect(m_revertFile, &QAction::triggered, this,
            [this] { m_workspace->document().revertToFile(); });
    connect(m_connect, &QAction::triggered, m_device, &DeviceController::connectDialog);
    connect(m_disconnect, &QAction::triggered, m_device, &DeviceController::disconnectFromDevice);
    connect(m_readAll, &QAction::triggered, m_device, &DeviceController::readAll);
    connect(m_writeChanges, &QAction::triggered, m_device, &DeviceController::writeChanges);
    connect(m_compareDevice, &QAction::triggered, m_device, &DeviceController::compareWithDevice);
    connect(m_scanNode, &QAction::triggered, m_device, &DeviceController::scan);
    connect(m_foldWizard, &QAction::triggered, this, [this] { openFoldWizard(); });
    connect(m_welcome, &WelcomePage::connectRequested, m_device, &DeviceController::connectDialog);
    connect(m_welcome, &WelcomePage::openRequested, m_files, &FileController::open);
    connect(m_welcome, &WelcomePage::newRequested, m_files, &FileController::newFile);
    connect(m_welcome, &WelcomePage::simulatorRequested, this,
            [this] { m_device->connectDialogOn(model::ConnectionKind::Sim); });
    connect(m_liveValues, &QAction::toggled, this,
            [this](bool on) { m_workspace->setLivePollRate(on ? 2.0 : 0.0); });
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("menuFile"));
    m_fileMenu->addActions({m_new, m_open, m_save, m_saveAs});
    m_recentMenu = m_fileMenu->addMenu(QString());
    m_recentMenu->setObjectName(QStringLiteral("menuRecent"));
    m_fileMenu->addActions({m_export, m_compareFile});
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_reportAction);
    m_fileMenu->addAction(m_sessionLogs);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_editMenu = menuBar()->addMenu(QString());
    m_editMenu->setObjectName(QStringLiteral("menuEdit"));
    m_editMenu->addActions({m_undo, m_redo});
    m_editMenu->addSeparator();
    m_editMenu->addActions({m_revertDevice, m_revertFile});

    m_deviceMenu = menuBar()->addMenu(QString());
    m_deviceMenu->setObjectName(QStringLiteral("menuDevice"));
    m_deviceMenu->addActions({m_connect, m_disconnect});
    m_deviceMenu->addSeparator();
    m_deviceMenu->addActions({m_readAll, m_writeChanges, m_compareDevice, m_liveValues});
    m_deviceMenu->addSeparator();
    m_deviceMenu->addActions({m_scanNode, m_foldWizard});

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("menuView"));

    m_languageMenu = menuBar()->addMenu(QString());
    m_languageMenu->setObjectName(QStringLiteral("menuLanguage"));
    m_languageMenu->addActions({m_english, m_german});

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("menuHelp"));
    m_helpMenu->addActions({m_guide, m_about});
    rebuildRecentMenu();
}

void MainWindow::connectWorkspace()
{
    model::ParameterDocument &doc = m_workspace->document();
    connect(m_files, &FileController::statusMessage, this, &MainWindow::showStatus);
    connect(m_files, &FileController::foldPlanRequested, this,
            [this](const QString &path) { openFoldWizard(path); });
    connect(m_device, &DeviceController::statusMessage, this, &MainWindow::showStatus);
    connect(doc.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&doc, &model::ParameterDocument::filePathChanged, this, [this] {
        updateTitle();
        updateActions();
    });
    connect(&doc, &model::ParameterDocument::modulesReset, this, &MainWindow::updateActions);
    connect(m_workspace, &Workspace::connecting, this, [this](const QString &description) {
        m_linkStatus->setConnection(m_workspace->connection(), {});
        showStatus(tr("Connecting to %1…").arg(description));
        updateActions();
    });
    // The wizard holds the connection: it lets go before the connection is destroyed.
    connect(m_workspace, &Workspace::aboutToDisconnect, this, [this] {
        m_monitor->clearConnection();
        m_workbench->clearConnection();
        m_inspector->clearConnection();
        m_linkStatus->clearConnection();
        if (m_wizard)
            m_wizard->setConnection(nullptr);
    });
    connect(m_workspace, &Workspace::connected, this, [this] {
        if (m_wizard)
            m_wizard->setConnection(m_workspace->connection());
        m_linkStatus->setModules(m_workspace->modules());
        m_nodeView->setNodeText(m_workspace->connection()->displayText());
        m_inspector->setConnection(m_workspace->connection(), m_workspace->modules());
        m_monitor->setConnection(m_workspace->connection(), m_workspace->modules());
        m_workbench->setConnection(&m_workspace->connection()->access(), m_workspace->modules());
        showStatus(tr("Connected: %n module(s).", nullptr,
                      static_cast<int>(m_workspace->modules().size())));
        updateActions();
        m_device->readAll(); // what the engineer does first anyway; the live d-values start with it
    });
    connect(m_workspace, &Workspace::scanFinished, this, [this] {
        m_monitor->setConnection(m_workspace->connection(), m_workspace->modules());
        m_workbench->setConnection(&m_workspace->connection()->access(), m_workspace->modules());
        m_linkStatus->setModules(m_workspace->modules());
        m_inspector->setConnection(m_workspace->connection(), m_workspace->modules());
    });
    connect(m_workspace, &Workspace::connectFailed, this, [this](const QString &reason) {
        m_linkStatus->clearConnection();
        showStatus(tr("Connection failed: %1").arg(reason));
        updateActions();
    });
    connect(m_workspace, &Workspace::disconnected, this, [this](const QString &reason) {
        m_linkStatus->clearConnection();
        m_nodeView->setNodeText(QString());
        m_inspector->clearConnection();
        QString text =
            reason.isEmpty() ? tr("Disconnected.") : tr("Connection lost: %1").arg(reason);
        // The link went away with set values the tool changed: say which could not be put back.
        QStringList left;
        for (const model::ActuatorChange &c : m_workspace->actuatorLedger().changes())
            left << tr("%1 on module %2").arg(QString::fromStdString(c.row->name)).arg(c.module);
        if (!reason.isEmpty() && !left.isEmpty())
            text += QLatin1Char(' ') + tr("Could not put back (link gone): %1. Check the axis.")
                                           .arg(left.join(QStringLiteral(", ")));
        showStatus(text);
        updateActions();
    });
}

ui::FoldWizard *MainWindow::openFoldWizard(const QString &planPath)
{
    const bool fresh = !m_wizard;
    if (!m_wizard) {
        m_wizard = new ui::FoldWizard(
            m_workspace->dictionaries(),
            m_workspace->isConnected() ? m_workspace->connection() : nullptr, this);
        m_wizard->setAttribute(Qt::WA_DeleteOnClose);
        // The apply's writes reach the tuning journal as every other write does.
        if (auto *apply =
                qobject_cast<ui::FoldApplyPage *>(m_wizard->page(ui::FoldWizard::ApplyPageId)))
            connect(apply, &ui::FoldApplyPage::applyFinished, this, [this, apply] {
                if (!apply->job())
                    return;
                for (const model::FoldApplyModule &m : apply->job()->modules())
                    if (!m.writes.empty())
                        m_monitor->journalWrites(m.current, m.writes);
            });
    } else if (m_workspace->isConnected()) {
        m_wizard->setConnection(m_workspace->connection());
    }
    if (!planPath.isEmpty()) {
        QString error;
        if (!m_wizard->openPlan(planPath, &error))
            showStatus(error);
    }
    if (fresh && m_wizard->online()) {
        // The wizard's checks compare the plan with the node: read the node (version and mode
        // of every module) before the first page is shown.
        showStatus(tr("Reading the connected node for the fold wizard …"));
        m_wizard->readNode([wizard = QPointer<ui::FoldWizard>(m_wizard), this] {
            if (!wizard)
                return;
            showStatus(tr("The fold wizard read %n module(s) of the connected node.", "",
                          static_cast<int>(wizard->nodeModules().size())));
            wizard->show();
            wizard->raise();
        });
        return m_wizard;
    }
    m_wizard->show();
    m_wizard->raise();
    return m_wizard;
}

void MainWindow::updateActions()
{
    const bool connected = m_workspace->isConnected();
    const bool busy = m_workspace->connection() && !connected;
    const model::ParameterDocument &doc = m_workspace->document();
    const bool hasModules = doc.moduleCount() > 0;
    m_connect->setEnabled(!busy);
    m_disconnect->setEnabled(m_workspace->connection() != nullptr);
    m_readAll->setEnabled(connected);
    m_writeChanges->setEnabled(connected);
    m_compareDevice->setEnabled(connected);
    m_scanNode->setEnabled(connected);
    m_save->setEnabled(hasModules);
    m_saveAs->setEnabled(hasModules);
    m_export->setEnabled(hasModules);
    m_reportAction->setEnabled(hasModules);
    m_compareFile->setEnabled(hasModules);
    m_revertDevice->setEnabled(hasModules);
    m_revertFile->setEnabled(doc.hasFile());
    const bool empty = !hasModules && !m_workspace->connection();
    m_centre->setCurrentWidget(empty ? static_cast<QWidget *>(m_welcome) : m_editor);
}

void MainWindow::updateTitle()
{
    const model::ParameterDocument &doc = m_workspace->document();
    const QString name = doc.hasFile() ? QFileInfo(doc.filePath()).fileName() : tr("Untitled");
    setWindowTitle(QStringLiteral("%1[*] — %2").arg(name, tr("ValveTune")));
    setWindowModified(doc.isModified());
}

void MainWindow::showStatus(const QString &text)
{
    statusBar()->showMessage(text, 8000);
}

void MainWindow::applyDocumentLanguage()
{
    m_workspace->document().setLanguage(m_language.current() == QLatin1String("de")
                                            ? dev::Language::German
                                            : dev::Language::English);
}

void MainWindow::retranslate()
{
    m_fileMenu->setTitle(tr("&File"));
    m_recentMenu->setTitle(tr("Open &Recent"));
    m_editMenu->setTitle(tr("&Edit"));
    m_deviceMenu->setTitle(tr("&Device"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_helpMenu->setTitle(tr("&Help"));

    m_new->setText(tr("&New…"));
    m_open->setText(tr("&Open…"));
    m_save->setText(tr("&Save"));
    m_saveAs->setText(tr("Save &As…"));
    m_export->setText(tr("&Export CSV…"));
    m_reportAction->setText(tr("Commissioning Re&port…"));
    m_compareFile->setText(tr("Compare with &File…"));
    m_sessionLogs->setText(tr("Open Session &Log Folder"));
    m_sessionLogs->setToolTip(tr("Every write of a session is kept in a log file in this folder."));
    m_quit->setText(tr("&Quit"));
    updateUndoActions();
    m_revertDevice->setText(tr("Revert to &Device"));
    m_revertFile->setText(tr("Revert to &File"));
    m_connect->setText(tr("&Connect…"));
    m_disconnect->setText(tr("&Disconnect"));
    m_readAll->setText(tr("&Read All"));
    m_writeChanges->setText(tr("&Write Changes…"));
    m_compareDevice->setText(tr("Compare with De&vice…"));
    m_liveValues->setText(tr("&Live Display Values"));
    m_scanNode->setText(tr("&Scan Node"));
    m_foldWizard->setText(tr("&Fold Wizard…"));
    m_english->setText(QStringLiteral("English")); // language names stay in their own language
    m_german->setText(QStringLiteral("Deutsch"));
    m_guide->setText(tr("&User Guide"));
    m_about->setText(tr("&About ValveTune…"));

    m_nodeDock->setWindowTitle(tr("Node"));
    m_monitorDock->setWindowTitle(tr("Monitor"));
    m_workbenchDock->setWindowTitle(tr("Workbench"));
    m_telegramsDock->setWindowTitle(tr("Telegrams"));
    m_curveDock->setWindowTitle(tr("Linearisation"));
    updateTitle();
    rebuildRecentMenu();
}

void MainWindow::updateUndoActions()
{
    const QUndoStack *undo = m_workspace->document().undoStack();
    m_undo->setEnabled(undo->canUndo());
    m_redo->setEnabled(undo->canRedo());
    m_undo->setText(undo->undoText().isEmpty() ? tr("&Undo")
                                               : tr("&Undo: %1").arg(undo->undoText()));
    m_redo->setText(undo->redoText().isEmpty() ? tr("&Redo")
                                               : tr("&Redo: %1").arg(undo->redoText()));
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = m_recent->files();
    if (files.isEmpty()) {
        m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
        return;
    }
    for (const QString &f : files) {
        QAction *a = m_recentMenu->addAction(QDir::toNativeSeparators(f));
        connect(a, &QAction::triggered, this, [this, f] {
            if (m_files->maybeSave())
                m_files->openPath(f);
        });
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("Clear List")), &QAction::triggered, m_recent,
            &model::RecentFiles::clear);
}

void MainWindow::chooseLanguage(const QString &code)
{
    if (m_language.setLanguage(code))
        m_settings.setLanguage(code);
}

void MainWindow::showAbout()
{
    ui::AboutDialog dialog(this);
    dialog.exec();
}

void MainWindow::openSessionLogFolder()
{
    const model::AuditLog *log = model::AuditLog::current();
    const QString folder = log ? log->directory() : model::AuditLog::defaultDirectory();
    // The folder exists before the first write, so the file manager has something to show.
    if (QDir().mkpath(folder) && QDesktopServices::openUrl(QUrl::fromLocalFile(folder)))
        return;
    QMessageBox::information(this, tr("Session Logs"),
                             tr("The session logs are kept in %1.").arg(folder));
}

void MainWindow::saveLayout()
{
    m_settings.setWindowGeometry(saveGeometry());
    m_settings.setWindowState(saveState());
    saveViewLayout(*this, m_settings.store());
    m_settings.setRecentFiles(m_recent->files());
    m_settings.sync();
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (m_viewLayoutRestored)
        return;
    m_viewLayoutRestored = true;
    // Splitters and columns take their remembered sizes once the first show has laid them out.
    QTimer::singleShot(0, this, [this] { restoreViewLayout(*this, m_settings.store()); });
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    // One question for all that is pending; once its answer is carried out (test stopped, values
    // put back), the QuitController closes the window again.
    if (!m_quitController->mayClose()) {
        event->ignore();
        return;
    }
    saveLayout();
    m_workspace->disconnectFromDevice();
    event->accept();
}

} // namespace vt::app
