#include "main_window.h"

#include "app_settings.h"
#include "language.h"
#include "model/recent_files.h"
#include "transports/link.h"
#include "widgets/about_dialog.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QStatusBar>

namespace vt::app {
namespace {

QLabel *hintLabel(QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setAlignment(Qt::AlignCenter);
    label->setWordWrap(true);
    label->setTextFormat(Qt::PlainText);
    label->setMargin(12);
    return label;
}

} // namespace

MainWindow::MainWindow(AppSettings &settings, Language &language, QWidget *parent)
    : QMainWindow(parent), m_settings(settings), m_language(language)
{
    setObjectName(QStringLiteral("MainWindow"));
    m_recent = new model::RecentFiles(model::RecentFiles::kDefaultLimit, this);
    m_recent->setFiles(m_settings.recentFiles());

    m_welcome = hintLabel(this);
    setCentralWidget(m_welcome);
    createActions();
    createMenus();
    createDocks();

    m_linkState = new QLabel(this);
    m_linkState->setObjectName(QStringLiteral("linkState"));
    statusBar()->addPermanentWidget(m_linkState);

    connect(m_recent, &model::RecentFiles::changed, this, &MainWindow::rebuildRecentMenu);
    connect(&m_language, &Language::languageChanged, this, [this](const QString &code) {
        m_english->setChecked(code == QLatin1String("en"));
        m_german->setChecked(code == QLatin1String("de"));
    });
    m_english->setChecked(m_language.current() != QLatin1String("de"));
    m_german->setChecked(m_language.current() == QLatin1String("de"));

    resize(1200, 800);
    restoreGeometry(m_settings.windowGeometry());
    restoreState(m_settings.windowState());
    retranslate();
}

MainWindow::~MainWindow() = default;

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
    m_quit = make("actionQuit", QKeySequence::Quit);
    m_connect = make("actionConnect");
    m_disconnect = make("actionDisconnect");
    m_readAll = make("actionReadAll");
    m_writeChanges = make("actionWriteChanges");
    m_scanNode = make("actionScanNode");
    m_foldWizard = make("actionFoldWizard");
    m_about = make("actionAbout");
    m_english = make("actionEnglish");
    m_german = make("actionGerman");

    // Features of later milestones: visible so users see what is coming, but disabled and
    // labelled as not available rather than pretending to work.
    m_notYetAvailable = {m_new, m_open, m_save, m_saveAs, m_export, m_connect, m_disconnect,
                         m_readAll, m_writeChanges, m_scanNode, m_foldWizard};
    for (QAction *a : m_notYetAvailable)
        a->setEnabled(false);

    auto *group = new QActionGroup(this);
    for (QAction *a : {m_english, m_german}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    connect(m_english, &QAction::triggered, this, [this] { chooseLanguage(QStringLiteral("en")); });
    connect(m_german, &QAction::triggered, this, [this] { chooseLanguage(QStringLiteral("de")); });
    connect(m_quit, &QAction::triggered, this, &QWidget::close);
    connect(m_about, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("menuFile"));
    m_fileMenu->addActions({m_new, m_open, m_save, m_saveAs});
    m_recentMenu = m_fileMenu->addMenu(QString());
    m_recentMenu->setObjectName(QStringLiteral("menuRecent"));
    m_fileMenu->addAction(m_export);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_deviceMenu = menuBar()->addMenu(QString());
    m_deviceMenu->setObjectName(QStringLiteral("menuDevice"));
    m_deviceMenu->addActions({m_connect, m_disconnect});
    m_deviceMenu->addSeparator();
    m_deviceMenu->addActions({m_readAll, m_writeChanges});
    m_deviceMenu->addSeparator();
    m_deviceMenu->addActions({m_scanNode, m_foldWizard});

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("menuView"));

    m_languageMenu = menuBar()->addMenu(QString());
    m_languageMenu->setObjectName(QStringLiteral("menuLanguage"));
    m_languageMenu->addActions({m_english, m_german});

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("menuHelp"));
    m_helpMenu->addAction(m_about);
    rebuildRecentMenu();
}

void MainWindow::createDocks()
{
    auto dock = [this](const char *name, QLabel *&hint, Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(this);
        d->setObjectName(QString::fromLatin1(name));
        hint = hintLabel(d);
        d->setWidget(hint);
        addDockWidget(area, d);
        m_viewMenu->addAction(d->toggleViewAction());
        return d;
    };
    m_parametersDock = dock("dockParameters", m_parametersHint, Qt::LeftDockWidgetArea);
    m_monitorDock = dock("dockMonitor", m_monitorHint, Qt::RightDockWidgetArea);
    m_telegramsDock = dock("dockTelegrams", m_telegramsHint, Qt::BottomDockWidgetArea);
}

void MainWindow::retranslate()
{
    setWindowTitle(tr("ValveTune"));
    m_fileMenu->setTitle(tr("&File"));
    m_recentMenu->setTitle(tr("Open &Recent"));
    m_deviceMenu->setTitle(tr("&Device"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_helpMenu->setTitle(tr("&Help"));

    m_new->setText(tr("&New…"));
    m_open->setText(tr("&Open…"));
    m_save->setText(tr("&Save"));
    m_saveAs->setText(tr("Save &As…"));
    m_export->setText(tr("&Export…"));
    m_quit->setText(tr("&Quit"));
    m_connect->setText(tr("&Connect…"));
    m_disconnect->setText(tr("&Disconnect"));
    m_readAll->setText(tr("&Read All"));
    m_writeChanges->setText(tr("&Write Changes…"));
    m_scanNode->setText(tr("&Scan Node"));
    m_foldWizard->setText(tr("&Fold Wizard…"));
    m_english->setText(QStringLiteral("English")); // language names stay in their own language
    m_german->setText(QStringLiteral("Deutsch"));
    m_about->setText(tr("&About ValveTune…"));
    for (QAction *a : std::as_const(m_notYetAvailable))
        a->setStatusTip(tr("Not available in this version yet"));

    m_parametersDock->setWindowTitle(tr("Parameters"));
    m_monitorDock->setWindowTitle(tr("Monitor"));
    m_telegramsDock->setWindowTitle(tr("Telegrams"));
    m_parametersHint->setText(tr("The parameters of the connected device or the open file appear here."));
    m_monitorHint->setText(tr("Live values of the connected device are plotted here."));
    m_telegramsHint->setText(tr("Every telegram sent and received is listed here."));
    m_welcome->setText(tr("No device connected and no parameter file open."));
    m_linkState->setText(link::linkStateText(link::LinkState::Closed));
    rebuildRecentMenu();
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
        QAction *a = m_recentMenu->addAction(f);
        a->setEnabled(false); // opening files arrives with the parameter-file milestone
        a->setStatusTip(tr("Not available in this version yet"));
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("Clear List")), &QAction::triggered, m_recent, &model::RecentFiles::clear);
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

void MainWindow::saveLayout()
{
    m_settings.setWindowGeometry(saveGeometry());
    m_settings.setWindowState(saveState());
    m_settings.setRecentFiles(m_recent->files());
    m_settings.sync();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveLayout();
    event->accept();
}

} // namespace vt::app
