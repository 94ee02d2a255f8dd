// The parameter editor end to end through the simulator: connect → read all → edit
// C1.07 to 1.000 V in the editor → write → the simulator holds raw 1000 → undo marks the row as
// differing from the device → save → reopen → compare shows no difference; an out-of-range entry
// is refused in the editor with the limits named; German input "1,5" in a volt field is raw 1500.
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/file_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "model/params/compare_model.h"
#include "model/params/device_jobs.h"
#include "model/params/param_file_io.h"
#include "model/params/param_roles.h"
#include "model/params/parameter_filter_model.h"
#include "model/params/parameter_tree_model.h"
#include "sim_rig.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/connect/link_status_widget.h"
#include "widgets/editor/compare_dialog.h"
#include "widgets/editor/map_report_dialog.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/editor/write_dialog.h"
#include "widgets/files/new_file_dialog.h"

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

namespace vt::test {
namespace {

using app::MainWindow;

struct EditorE2E : ::testing::Test
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<MainWindow> window;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        window = std::make_unique<MainWindow>(settings, language);
        window->show();
        window->files().setPromptHook([] { return QMessageBox::Discard; });
    }

    void connectSimulator()
    {
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = "dma-pn-v51";
        window->device().connectTo(spec); // reads all once connected
        ASSERT_TRUE(read.wait(kWaitMs));
        ASSERT_TRUE(read.at(0).at(0).toBool());
    }

    const dev::ParamMeta *row(const char *name) const
    {
        return window->workspace().document().module(0).dictionary->find(name);
    }

    // Types `text` into the value cell of `name` through the real delegate and presses Enter.
    void typeValue(const char *name, const QString &text)
    {
        ui::ParameterEditor *editor = window->editor();
        ASSERT_TRUE(editor->selectParameter(0, row(name)));
        QTreeView *view = editor->view();
        view->edit(view->currentIndex());
        auto *line = view->viewport()->findChild<QLineEdit *>();
        ASSERT_NE(line, nullptr);
        line->selectAll();
        QTest::keyClicks(line, text);
        QTest::keyClick(line, Qt::Key_Return);
        QCoreApplication::processEvents();
    }

    std::optional<dev::RawValue> working(const char *name) const
    {
        return window->workspace().document().value(0, row(name));
    }
};

TEST_F(EditorE2E, EditWriteUndoSaveReopenCompare)
{
    connectSimulator();
    typeValue("C1.07", QStringLiteral("1.000"));
    EXPECT_EQ(working("C1.07"), dev::RawValue{1000.0});
    EXPECT_TRUE(window->workspace().document().differsFromDevice(0, row("C1.07")));

    ui::WriteDialog *dialog = window->device().writeChanges();
    ASSERT_NE(dialog, nullptr);
    ASSERT_EQ(dialog->table()->rowCount(), 1); // only the changed value
    EXPECT_EQ(dialog->table()->item(0, 1)->text(), "C1.07");
    EXPECT_EQ(dialog->table()->item(0, 4)->text(), "1.000 V");
    QSignalSpy finished(dialog, &ui::WriteDialog::writeFinished);
    dialog->confirm();
    ASSERT_TRUE(finished.wait(kWaitMs));
    EXPECT_TRUE(finished.at(0).at(0).toBool());
    EXPECT_TRUE(dialog->table()->item(0, 5)->text().startsWith("verified", Qt::CaseInsensitive))
        << dialog->table()->item(0, 5)->text().toStdString();
    model::SimEndpoint *sim = window->workspace().connection()->simEndpoint();
    EXPECT_EQ(storedRaw(sim->node()->module(0), *row("C1.07")), 1000.0);
    dialog->close();

    // Undo after the write: the editor value goes back, the row differs from the device.
    window->workspace().document().undoStack()->undo();
    const QModelIndex source = window->editor()->treeModel()->indexOf(0, row("C1.07"));
    EXPECT_TRUE(source.data(model::DiffersFromDeviceRole).toBool());
    window->workspace().document().undoStack()->redo();
    EXPECT_FALSE(source.data(model::DiffersFromDeviceRole).toBool());

    const QString path = dir.filePath("press.vtpar");
    ASSERT_TRUE(window->files().saveTo(path)) << window->files().lastError().toStdString();
    ASSERT_TRUE(window->files().openPath(path)) << window->files().lastError().toStdString();
    EXPECT_EQ(working("C1.07"), dev::RawValue{1000.0});
    QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
    window->device().readAll();
    ASSERT_TRUE(read.wait(kWaitMs));
    qRegisterMetaType<ui::CompareDialog *>();
    QSignalSpy compared(&window->device(), &app::DeviceController::compareDialogOpened);
    window->device().compareWithDevice(); // reads the compared rows first
    ASSERT_TRUE(compared.wait(kWaitMs));
    auto *compare = window->findChild<ui::CompareDialog *>();
    ASSERT_NE(compare, nullptr);
    EXPECT_EQ(compare->compareModel()->rowCount(), 0);
    // Nothing to choose: only Close is offered, and Enter closes.
    EXPECT_FALSE(compare->tickAllButton()->isEnabled());
    EXPECT_FALSE(compare->tickNoneButton()->isEnabled());
    EXPECT_FALSE(compare->applyButton()->isEnabled());
    EXPECT_TRUE(compare->closeButton()->isEnabled());
    EXPECT_TRUE(compare->closeButton()->isDefault());
}

TEST_F(EditorE2E, OutOfRangeIsRefusedInTheEditorWithTheLimits)
{
    connectSimulator();
    const auto before = working("C1.07");
    typeValue("C1.07", QStringLiteral("12"));
    EXPECT_EQ(working("C1.07"), before);
    QLabel *message = window->editor()->messageLabel();
    EXPECT_TRUE(message->isVisible());
    EXPECT_TRUE(message->text().contains(QStringLiteral("9.999"))) << message->text().toStdString();
    EXPECT_TRUE(message->text().contains(QStringLiteral("C1.07")));
}

TEST_F(EditorE2E, GermanLocaleTakesTheDecimalComma)
{
    ASSERT_TRUE(language.setLanguage("de"));
    QCoreApplication::processEvents();
    connectSimulator();
    typeValue("C1.07", QStringLiteral("1,5"));
    EXPECT_EQ(working("C1.07"), dev::RawValue{1500.0});
    const QModelIndex value = window->editor()->treeModel()->indexOf(
        0, row("C1.07"), model::ParameterTreeModel::ColValue);
    EXPECT_EQ(value.data().toString(), "1,500 V");
}

TEST_F(EditorE2E, LiveDisplayValuesArriveWithoutDisturbingAnEdit)
{
    connectSimulator();
    ui::ParameterEditor *editor = window->editor();
    ASSERT_TRUE(editor->selectParameter(0, row("C1.07")));
    editor->view()->edit(editor->view()->currentIndex());
    auto *line = editor->view()->viewport()->findChild<QLineEdit *>();
    ASSERT_NE(line, nullptr);
    line->setText(QStringLiteral("0.5"));
    // A stale display value is replaced by the slow poll while the editor stays open with its text.
    window->workspace().deviceImage().recordRead(1, {{row("d1.11"), 12345.0}});
    ASSERT_EQ(working("d1.11"), dev::RawValue{12345.0});
    ASSERT_TRUE(waitUntil([&] { return working("d1.11") != dev::RawValue{12345.0}; }));
    EXPECT_EQ(line->text(), "0.5");
    EXPECT_TRUE(line->isVisible());
}

} // namespace
} // namespace vt::test

namespace vt::test {
namespace {

TEST_F(EditorE2E, NewFileFromTheDictionaryDefaultsAndConnectThroughTheDialog)
{
    // File ▸ New: the dialog's choice becomes a document with the dictionary's defaults.
    window->findChild<QAction *>("actionNew")->trigger();
    auto *newDialog = window->findChild<ui::NewFileDialog *>();
    ASSERT_NE(newDialog, nullptr);
    ASSERT_TRUE(newDialog->setFamily("dma-pn-v51"));
    const int modules = newDialog->choice().modules;
    newDialog->accept(); // the dialog deletes itself on close
    QCoreApplication::processEvents();
    ASSERT_EQ(window->workspace().document().moduleCount(), modules);
    const dev::ParamMeta *c107 = row("C1.07");
    EXPECT_EQ(working("C1.07"), dev::RawValue{*c107->defaultValue});
    EXPECT_FALSE(window->workspace().document().hasFile());

    // Device ▸ Connect…: the dialog's spec connects, the status bar names the link and counts.
    window->findChild<QAction *>("actionConnect")->trigger();
    auto *connectDialog = window->findChild<ui::ConnectDialog *>();
    ASSERT_NE(connectDialog, nullptr);
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    connectDialog->setSpec(spec);
    QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
    connectDialog->accept();
    ASSERT_TRUE(read.wait(kWaitMs));
    EXPECT_TRUE(window->linkStatus()->linkText().contains("dma-pn-v51"))
        << window->linkStatus()->linkText().toStdString();
    EXPECT_TRUE(window->workspace().document().module(0).online);
    // The new document's module 1 paired with the device's: its values now differ where the
    // simulator's stored values are not the defaults, and nothing was written.
    EXPECT_EQ(window->workspace().document().moduleCount(), modules);
}

} // namespace
} // namespace vt::test

namespace vt::test {
namespace {

TEST_F(EditorE2E, UnsavedChangesPromptAndReadAllCancel)
{
    connectSimulator();
    const QString path = dir.filePath("kept.vtpar");
    ASSERT_TRUE(window->files().saveTo(path));
    typeValue("C1.07", QStringLiteral("1.234"));
    ASSERT_TRUE(window->workspace().document().isModified());

    // Cancel keeps the edit and refuses to go on; Save writes it first; Discard goes on.
    window->files().setPromptHook([] { return QMessageBox::Cancel; });
    EXPECT_FALSE(window->files().maybeSave());
    EXPECT_TRUE(window->workspace().document().isModified());
    window->files().setPromptHook([] { return QMessageBox::Save; });
    EXPECT_TRUE(window->files().maybeSave());
    EXPECT_FALSE(window->workspace().document().isModified());
    auto saved = model::readParamFile(path, dev::Language::English);
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved->modules[0].find("C1.07")->raw, dev::RawValue{1234.0});

    // Read All can be cancelled: the job ends incomplete and says so.
    QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
    window->device().readAll();
    ASSERT_NE(window->device().readJob(), nullptr);
    window->device().readJob()->cancel();
    ASSERT_TRUE(read.wait(kWaitMs));
    EXPECT_FALSE(read.at(0).at(0).toBool());
}

TEST_F(EditorE2E, FileOfAnotherVersionReportsWhatDidNotMap)
{
    dev::files::ParamFile file;
    dev::files::ModuleRecord record;
    record.address = 1;
    record.family = "dma-pn-v51";
    record.version = "51";
    record.mode = "3";
    record.values.push_back(dev::files::makeValueRow(
        *dev::builtinDictionaries()->find("dma-pn-v51")->find("C1.07"), 700.0));
    dev::files::ValueRow future;
    future.name = "C1.99";
    future.raw = 5.0;
    record.values.push_back(future);
    file.modules.push_back(record);
    const QString path = dir.filePath("newer.vtpar");
    ASSERT_FALSE(
        model::saveParamFile(path, file, *dev::builtinDictionaries(), dev::Language::English));
    ASSERT_TRUE(window->files().openPath(path));
    ASSERT_TRUE(ui::MapReportDialog::needed(window->workspace().document()));
    ui::MapReportDialog report(window->workspace().document());
    EXPECT_TRUE(report.text().contains("C1.99")) << report.text().toStdString();
    // Kept and written back on save.
    const QString again = dir.filePath("again.vtpar");
    ASSERT_TRUE(window->files().saveTo(again));
    auto reread = model::readParamFile(again, dev::Language::English);
    ASSERT_TRUE(reread.ok());
    ASSERT_NE(reread->modules[0].find("C1.99"), nullptr);
}

// Compare: "Tick All" only ticks, and the Apply button and the line above it say what applying
// will change (how many values, into the document, not the device).
TEST_F(EditorE2E, CompareSaysWhatApplyWillChange)
{
    connectSimulator();
    const auto device = working("C1.07");
    typeValue("C1.07", QStringLiteral("2.5"));
    ASSERT_NE(working("C1.07"), device);
    qRegisterMetaType<ui::CompareDialog *>();
    QSignalSpy compared(&window->device(), &app::DeviceController::compareDialogOpened);
    window->device().compareWithDevice();
    ASSERT_TRUE(compared.wait(kWaitMs));
    auto *compare = window->findChild<ui::CompareDialog *>();
    ASSERT_NE(compare, nullptr);
    ASSERT_EQ(compare->compareModel()->rowCount(), 1);
    EXPECT_FALSE(compare->applyButton()->isEnabled());
    EXPECT_TRUE(compare->tickAllButton()->isEnabled());
    EXPECT_TRUE(compare->tickNoneButton()->isEnabled());
    EXPECT_FALSE(compare->closeButton()->isDefault());
    compare->findChild<QPushButton *>(QStringLiteral("compareTickAll"))->click();
    EXPECT_EQ(working("C1.07"), dev::RawValue{2500.0}); // ticking changes nothing yet
    EXPECT_TRUE(compare->applyButton()->isEnabled());
    EXPECT_EQ(compare->applyButton()->text(), "Apply 1 Ticked Value");
    EXPECT_TRUE(compare->effectLabel()->text().contains(QStringLiteral("Write Changes")))
        << compare->effectLabel()->text().toStdString();
    compare->applyButton()->click();
    EXPECT_EQ(working("C1.07"), device);
}

} // namespace
} // namespace vt::test
