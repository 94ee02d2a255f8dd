// German and English at run time: with the editor, monitor, inspector and fold wizard
// open and a device connected, one switch of the Language menu changes the visible texts of each
// — menus, the editor's filters and column headers, the plot axis, the inspector's tabs, the
// wizard page — and numbers follow ("1,000 V"); switching back restores English.
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "model/params/parameter_tree_model.h"
#include "test_wait.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_plot.h"
#include "widgets/monitor/monitor_view.h"

#include <QAction>
#include <QCheckBox>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

QString tr(const char *context, const char *text)
{
    return QCoreApplication::translate(context, text);
}

struct Texts
{
    QString menu, filter, header, axis, tab, wizardPage, value;
};

Texts visible(app::MainWindow &w)
{
    Texts t;
    t.menu = w.menuBar()->actions().first()->text();
    t.filter = w.editor()->findChild<QCheckBox *>("filterChanged")->text();
    t.header = w.editor()
                   ->treeModel()
                   ->headerData(model::ParameterTreeModel::ColValue, Qt::Horizontal)
                   .toString();
    t.axis = w.monitor()->plot()->xAxis->label();
    t.tab = w.inspector()->findChild<QTabWidget *>()->tabText(0);
    ui::FoldWizard *wizard = w.findChild<ui::FoldWizard *>();
    t.wizardPage = wizard && wizard->currentPage() ? wizard->currentPage()->title() : QString();
    const model::ParamModule &m = w.workspace().document().module(0);
    t.value = w.editor()
                  ->treeModel()
                  ->indexOf(0, m.dictionary->find("C1.07"), model::ParameterTreeModel::ColValue)
                  .data()
                  .toString();
    return t;
}

TEST(LanguageSwitch, EveryOpenWindowFollowsAtOnce)
{
    QTemporaryDir dir;
    app::AppSettings settings(dir.filePath("settings.ini"));
    app::Language language;
    ASSERT_TRUE(language.setLanguage("en"));
    app::MainWindow w(settings, language);
    w.show();
    QSignalSpy read(&w.device(), &app::DeviceController::readFinished);
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    w.device().connectTo(spec);
    ASSERT_TRUE(read.wait(vt::test::kWaitMs));
    const dev::ParamMeta *c107 = w.workspace().document().module(0).dictionary->find("C1.07");
    w.workspace().document().edit(0, c107, 1000.0);
    ui::FoldWizard *wizard = w.openFoldWizard();
    // The wizard reads the node before it shows its first page.
    ASSERT_TRUE(vt::test::waitUntil([&] { return wizard->isVisible(); }, vt::test::kWaitMs));
    QCoreApplication::processEvents();

    const Texts english = visible(w);
    EXPECT_EQ(english.menu, "&File");
    EXPECT_EQ(english.filter, "Changed only");
    EXPECT_EQ(english.header, "Value");
    EXPECT_EQ(english.axis, "time (s)");
    EXPECT_EQ(english.wizardPage, "Node type");
    EXPECT_EQ(english.value, "1.000 V");

    w.findChild<QAction *>("actionGerman")->trigger();
    QCoreApplication::processEvents();
    const Texts german = visible(w);
    EXPECT_EQ(german.menu, "&Datei");
    EXPECT_EQ(german.filter, tr("vt::ui::ParameterEditor", "Changed only"));
    EXPECT_EQ(german.header, tr("vt::model::ParameterTreeModel", "Value"));
    EXPECT_EQ(german.axis, tr("vt::ui::MonitorPlot", "time (s)"));
    EXPECT_EQ(german.wizardPage, tr("vt::ui::FoldNodePage", "Node type"));
    EXPECT_EQ(german.value, "1,000 V");
    // Each text really is German now (the catalogue has it, and the widget took it).
    EXPECT_NE(german.filter, english.filter);
    EXPECT_NE(german.header, english.header);
    EXPECT_NE(german.axis, english.axis);
    EXPECT_NE(german.tab, english.tab);
    EXPECT_NE(german.wizardPage, english.wizardPage);

    w.findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    const Texts back = visible(w);
    EXPECT_EQ(back.menu, english.menu);
    EXPECT_EQ(back.filter, english.filter);
    EXPECT_EQ(back.tab, english.tab);
    EXPECT_EQ(back.wizardPage, english.wizardPage);
    EXPECT_EQ(back.value, english.value);
}

} // namespace
} // namespace vt::test
