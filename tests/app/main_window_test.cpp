#include "app/gui/app_settings.h"
#include "app/gui/file_controller.h"
#include "app/gui/gui_options.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/startup.h"
#include "app/gui/welcome_page.h"
#include "app/gui/workspace.h"
#include "dict/dictionary_loader.h"
#include "qt_printers.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/connect/link_status_widget.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/user_guide_dialog.h"

#include <QAction>
#include <QCommandLinkButton>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSplitter>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTreeView>
#include <gtest/gtest.h>

using namespace vt::app;

namespace {

QStringList menuTitles(const MainWindow &w)
{
    QStringList titles;
    for (QAction *a : w.menuBar()->actions())
        titles << a->text();
    return titles;
}

QStringList actionTexts(const MainWindow &w, const char *menuName)
{
    QStringList texts;
    auto *menu = w.findChild<QMenu *>(QString::fromLatin1(menuName));
    if (!menu)
        return texts;
    for (QAction *a : menu->actions())
        if (!a->isSeparator())
            texts << a->text();
    return texts;
}

struct Fixture : ::testing::Test
{
    QTemporaryDir dir;
    AppSettings settings{dir.filePath("settings.ini")};
    Language language;

    void SetUp() override { ASSERT_TRUE(language.setLanguage("en")); }
};

} // namespace

TEST_F(Fixture, OpensWithItsMenusDocksAndStatusBar)
{
    MainWindow w(settings, language);
    w.show();
    EXPECT_EQ(menuTitles(w),
              (QStringList{"&File", "&Edit", "&Device", "&View", "&Language", "&Help"}));
    EXPECT_EQ(actionTexts(w, "menuFile"),
              (QStringList{"&New…", "&Open…", "&Save", "Save &As…", "Open &Recent", "&Export CSV…",
                           "Compare with &File…", "Commissioning Re&port…",
                           "Open Session &Log Folder", "&Quit"}));
    EXPECT_EQ(actionTexts(w, "menuDevice"),
              (QStringList{"&Connect…", "&Disconnect", "&Read All", "&Write Changes…",
                           "Compare with De&vice…", "&Live Display Values", "&Scan Node",
                           "&Fold Wizard…"}));
    EXPECT_EQ(actionTexts(w, "menuView"),
              (QStringList{"Node", "Monitor", "Telegrams", "Linearisation", "Workbench"}));
    EXPECT_EQ(actionTexts(w, "menuLanguage"), (QStringList{"English", "Deutsch"}));

    for (QDockWidget *d : {w.nodeDock(), w.monitorDock(), w.telegramsDock()}) {
        ASSERT_NE(d, nullptr);
        EXPECT_TRUE(d->isVisible());
    }
    EXPECT_EQ(w.linkStatus()->linkText(), "Not connected");
    // Without a connection the device actions that need one are disabled.
    EXPECT_TRUE(w.findChild<QAction *>("actionConnect")->isEnabled());
    EXPECT_FALSE(w.findChild<QAction *>("actionReadAll")->isEnabled());
    EXPECT_FALSE(w.findChild<QAction *>("actionSave")->isEnabled());
}

// Every bottom dock is tabbed with the others, so the tallest one's minimum sets the height of
// them all: at the default size for a 1366 × 768 laptop the editor keeps the larger part.
TEST_F(Fixture, TheBottomDocksLeaveTheEditorMostOfTheDefaultWindow)
{
    MainWindow w(settings, language);
    w.show();
    QCoreApplication::processEvents();
    ASSERT_LE(w.height(), 768);
    EXPECT_LT(w.monitorDock()->height(), w.height() / 2) << w.monitorDock()->height();
}

// "valvetune FILE", as the desktop entry (Exec=valvetune %f) starts it for a double-clicked file:
// a parameter file opens in the editor, a fold plan in the fold wizard.
TEST_F(Fixture, TheFileOnTheCommandLineOpens)
{
    const QString vtpar = dir.filePath("press 1.vtpar");
    QFile file(vtpar);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": [
        {"address": 1, "family": "dma-pb-v32", "version": "32.10", "mode": "3", "values": [
            {"name": "C1.07", "id": 48, "raw": 1250, "display": "1.250 V"}]}]})");
    file.close();

    MainWindow w(settings, language);
    w.files().setPromptHook([] { return QMessageBox::Discard; }); // no map report dialog
    w.show();
    const GuiOptions options = parseGuiOptions({"valvetune", vtpar});
    ASSERT_FALSE(options.exitNow) << options.error.toStdString();
    startFromOptions(w, options);
    EXPECT_TRUE(w.files().lastError().isEmpty()) << w.files().lastError().toStdString();
    EXPECT_EQ(w.workspace().document().filePath(), vtpar);

    const QString plan = QStringLiteral(VT_SOURCE_DIR "/tests/fuzz/fold/seeds/opat_3.vtfold");
    startFromOptions(w, parseGuiOptions({"valvetune", plan}));
    auto *wizard = w.findChild<vt::ui::FoldWizard *>();
    ASSERT_NE(wizard, nullptr);
    EXPECT_EQ(wizard->plan().modules.size(), 3u);
}

TEST_F(Fixture, SwitchingToGermanRetranslatesAtRunTime)
{
    MainWindow w(settings, language);
    w.show();
    auto *german = w.findChild<QAction *>("actionGerman");
    ASSERT_NE(german, nullptr);
    german->trigger();
    QCoreApplication::processEvents(); // QApplication posts LanguageChange to every window
    EXPECT_EQ(language.current(), "de");
    EXPECT_TRUE(german->isChecked());
    EXPECT_EQ(menuTitles(w),
              (QStringList{"&Datei", "&Bearbeiten", "&Gerät", "&Ansicht", "&Sprache", "&Hilfe"}));
    EXPECT_EQ(actionTexts(w, "menuDevice"),
              (QStringList{"&Verbinden…", "&Trennen", "Alle &lesen", "Änderungen &schreiben…",
                           "Mit &Gerät vergleichen…", "&Live-Anzeigewerte", "Knoten &abfragen",
                           "&Knoten-Assistent…"}));
    EXPECT_EQ(w.nodeDock()->windowTitle(), "Knoten");
    // One German word for Redo, the one Qt's own text fields use (docs/GLOSSARY-DE.md).
    EXPECT_EQ(w.findChild<QAction *>("actionRedo")->text(), "Wieder&herstellen");
    EXPECT_EQ(w.findChild<QAction *>("actionUndo")->text(), "&Rückgängig");
    EXPECT_EQ(w.linkStatus()->linkText(), "Nicht verbunden");
    EXPECT_EQ(settings.language(), "de"); // the choice is remembered

    w.findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    EXPECT_EQ(menuTitles(w).first(), "&File");
    EXPECT_EQ(w.linkStatus()->linkText(), "Not connected");
}

TEST_F(Fixture, LayoutIsKeptInTheSettings)
{
    const vt::dev::Dictionary &dma = *vt::dev::builtinDictionaries()->find("dma-pn-v51");
    int helpWidth = 0;
    {
        MainWindow w(settings, language);
        w.show();
        w.workspace().document().createNew({&dma, "51", "3", 1, 1},
                                           *vt::dev::builtinDictionaries());
        w.resize(1700, 1050);
        w.telegramsDock()->hide();
        // Column widths and splitters as the user left them.
        w.editor()->view()->setColumnWidth(2, 333);
        w.findChild<QSplitter *>("editorSplitter")->setSizes({900, 420});
        helpWidth = w.findChild<QSplitter *>("editorSplitter")->sizes().at(1);
        ASSERT_GT(helpWidth, 380); // not the default (about a fifth)
        w.saveLayout();
    }
    MainWindow again(settings, language);
    again.show();
    QCoreApplication::processEvents(); // the sizes come once the first show laid the window out
    // The editor (behind the welcome page until there is a document) keeps them too.
    again.workspace().document().createNew({&dma, "51", "3", 1, 1},
                                           *vt::dev::builtinDictionaries());
    QCoreApplication::processEvents();
    EXPECT_FALSE(again.telegramsDock()->isVisible());
    EXPECT_TRUE(again.nodeDock()->isVisible());
    EXPECT_EQ(again.size(), QSize(1700, 1050));
    EXPECT_EQ(again.editor()->view()->columnWidth(2), 333);
    EXPECT_NEAR(again.findChild<QSplitter *>("editorSplitter")->sizes().at(1), helpWidth, 8);
}

// With neither a device nor a file the window says how to start, as buttons that do it.
TEST_F(Fixture, AnEmptyWindowOffersTheWaysToStart)
{
    MainWindow w(settings, language);
    w.show();
    WelcomePage *welcome = w.welcomePage();
    ASSERT_NE(welcome, nullptr);
    EXPECT_TRUE(welcome->isVisible());
    EXPECT_FALSE(w.editor()->isVisible());
    EXPECT_EQ(welcome->connectButton()->text(), "Connect…");
    EXPECT_EQ(welcome->openButton()->text(), "Open…");
    EXPECT_EQ(welcome->newButton()->text(), "New…");

    welcome->simulatorButton()->click();
    auto *dialog = w.findChild<vt::ui::ConnectDialog *>();
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->isVisible());
    EXPECT_EQ(dialog->kind(), vt::model::ConnectionKind::Sim);
    dialog->reject();

    // A document: the editor takes the place.
    const vt::dev::Dictionary &dma = *vt::dev::builtinDictionaries()->find("dma-pn-v51");
    w.workspace().document().createNew({&dma, "51", "3", 1, 1}, *vt::dev::builtinDictionaries());
    EXPECT_FALSE(welcome->isVisible());
    EXPECT_TRUE(w.editor()->isVisible());
}

// Help ▸ User Guide: the guide inside the application, in the UI language, again on a switch.
TEST_F(Fixture, TheUserGuideIsInTheApplicationInBothLanguages)
{
    MainWindow w(settings, language);
    w.show();
    EXPECT_TRUE(actionTexts(w, "menuHelp").contains("&User Guide"));
    w.findChild<QAction *>("actionUserGuide")->trigger();
    auto *guide = w.findChild<vt::ui::UserGuideDialog *>();
    ASSERT_NE(guide, nullptr);
    EXPECT_TRUE(guide->isVisible());
    const QString en = guide->browser()->toPlainText();
    EXPECT_TRUE(en.contains("Trust rules")) << en.toStdString();
    EXPECT_TRUE(en.contains("ValveTune.conf"));
    w.findChild<QAction *>("actionGerman")->trigger();
    QCoreApplication::processEvents();
    const QString de = guide->browser()->toPlainText();
    EXPECT_TRUE(de.contains("Wo Dateien landen")) << de.toStdString();
    // Both texts have the same chapters.
    const auto headings = [](const QString &markdown) { return markdown.count("\n## "); };
    EXPECT_EQ(headings(vt::ui::UserGuideDialog::guideText("en")),
              headings(vt::ui::UserGuideDialog::guideText("de")));
    EXPECT_GE(headings(vt::ui::UserGuideDialog::guideText("en")), 4);
}

TEST(Language, RejectsUnknownCodesAndKeepsTheCurrentOne)
{
    Language l;
    ASSERT_TRUE(l.setLanguage("de"));
    EXPECT_FALSE(l.setLanguage("fr"));
    EXPECT_EQ(l.current(), "de");
    EXPECT_EQ(QLocale().toString(1.5, 'f', 3), "1,500"); // numbers follow the language
    ASSERT_TRUE(l.setLanguage("en"));
    EXPECT_EQ(QLocale().toString(1.5, 'f', 3), "1.500");
}
