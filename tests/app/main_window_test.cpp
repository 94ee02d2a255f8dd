#include "app/gui/app_settings.h"
#include "app/gui/file_controller.h"
#include "app/gui/gui_options.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/startup.h"
#include "app/gui/workspace.h"
#include "qt_printers.h"
#include "widgets/connect/link_status_widget.h"
#include "widgets/fold/fold_wizard.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
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
                           "Compare with &File…", "&Quit"}));
    EXPECT_EQ(actionTexts(w, "menuDevice"),
              (QStringList{"&Connect…", "&Disconnect", "&Read All", "&Write Changes…",
                           "Compare with De&vice…", "&Live Display Values", "&Scan Node",
                           "&Fold Wizard…"}));
    EXPECT_EQ(actionTexts(w, "menuView"),
              (QStringList{"Node", "Monitor", "Telegrams", "Linearisation"}));
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
    EXPECT_EQ(w.linkStatus()->linkText(), "Nicht verbunden");
    EXPECT_EQ(settings.language(), "de"); // the choice is remembered

    w.findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    EXPECT_EQ(menuTitles(w).first(), "&File");
    EXPECT_EQ(w.linkStatus()->linkText(), "Not connected");
}

TEST_F(Fixture, LayoutIsKeptInTheSettings)
{
    {
        MainWindow w(settings, language);
        w.show();
        w.resize(1700, 1050);
        w.telegramsDock()->hide();
        w.saveLayout();
    }
    MainWindow again(settings, language);
    again.show();
    EXPECT_FALSE(again.telegramsDock()->isVisible());
    EXPECT_TRUE(again.nodeDock()->isVisible());
    EXPECT_EQ(again.size(), QSize(1700, 1050));
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
