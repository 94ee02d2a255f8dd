// Trust, as a user meets it across windows on the built-in simulator: the editor's Device column
// is what is on the device after a step from the monitor; New and Open while connected keep the
// Device column and Write Changes offers exactly what differs, never "(unknown)", never a bus set
// value; a step, "Set E17 = 2" and a Write of E17 are asked first (unless the step is armed); what
// the tool changed is offered back on disconnect and quit. Each test failed on the first version.
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/file_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "model/params/compare_model.h"
#include "model/params/parameter_tree_model.h"
#include "sim_rig.h"
#include "widgets/actuator_confirm.h"
#include "widgets/editor/compare_dialog.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/editor/write_dialog.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>

namespace vt::test {
namespace {

using app::MainWindow;

struct TrustE2E : ::testing::Test
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<MainWindow> window;
    QList<QStringList> asked; // every actuator question, as asked
    bool answer = true;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        qRegisterMetaType<ui::CompareDialog *>();
        qRegisterMetaType<ui::WriteDialog *>();
        ui::setActuatorAnswerHook([this](const QStringList &lines) {
            asked.push_back(lines);
            return answer;
        });
        window = std::make_unique<MainWindow>(settings, language);
        window->show();
        window->files().setPromptHook([] { return QMessageBox::Discard; });
    }

    void TearDown() override
    {
        answer = false; // nothing is put back while the window closes
        window.reset();
        ui::setActuatorAnswerHook({});
    }

    void connectSimulator(std::size_t modules = 1)
    {
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = "dma-pn-v51";
        spec.sim.modules = modules;
        spec.sim.factory = true;          // E17 = 0: the step asks for "Set E17 = 2" first
        window->device().connectTo(spec); // reads all once connected
        ASSERT_TRUE(read.wait(kWaitMs));
        ASSERT_TRUE(read.at(0).at(0).toBool());
    }

    model::ParameterDocument &doc() { return window->workspace().document(); }
    const dev::ParamMeta *row(const char *name) { return doc().module(0).dictionary->find(name); }
    dev::sim::HcsModule &simModule(std::size_t i = 0)
    {
        return window->workspace().connection()->simEndpoint()->node()->module(i);
    }
    QString deviceText(int module, const char *name)
    {
        const dev::ParamMeta *r = doc().module(module).dictionary->find(name);
        return window->editor()
            ->treeModel()
            ->indexOf(module, r, model::ParameterTreeModel::ColDevice)
            .data()
            .toString();
    }
    ui::StepControl *step() { return window->monitor()->stepControl(); }

    // E17 = 2, then A1.01 = 2.000 V, as the engineer does it in the monitor.
    void stepTo2V()
    {
        ASSERT_TRUE(step()->selectTarget(1, QStringLiteral("A1.01")));
        QSignalSpy written(step(), &ui::StepControl::written);
        step()->enableBusSetValue();
        ASSERT_TRUE(written.wait(kWaitMs)) << step()->statusText().toStdString();
        step()->setStepValue(2.0);
        step()->writeStep();
        ASSERT_TRUE(waitUntil([&] { return written.count() == 2; }))
            << step()->statusText().toStdString();
        ASSERT_TRUE(written.at(1).at(2).toBool()) << step()->statusText().toStdString();
    }

    // Write Changes, with the pre-read when one is needed.
    ui::WriteDialog *openWrite()
    {
        QSignalSpy opened(&window->device(), &app::DeviceController::writeDialogOpened);
        if (ui::WriteDialog *now = window->device().writeChanges())
            return now;
        if (!window->device().readJob() || !opened.wait(kWaitMs)) // nothing to write, or no read
            return nullptr;
        return opened.at(0).at(0).value<ui::WriteDialog *>();
    }
};

TEST_F(TrustE2E, AStepFromTheMonitorShowsInTheEditorsDeviceColumnAndInCompare)
{
    connectSimulator();
    EXPECT_FALSE(deviceText(0, "E17").isEmpty()); // read by the connect
    ASSERT_NO_FATAL_FAILURE(stepTo2V());
    EXPECT_EQ(storedRaw(simModule(), *row("A1.01")), 2000.0);
    EXPECT_TRUE(deviceText(0, "A1.01").startsWith("2.000")) << deviceText(0, "A1.01").toStdString();
    EXPECT_EQ(deviceText(0, "E17"), "only 4 digital active"); // E17 = 2
    EXPECT_EQ(doc().value(0, row("E17"), model::Layer::Device), dev::RawValue{2.0});

    // Saved before the step as a file with E17 = 0: Compare with Device names E17, never the
    // bus set value.
    const QString path = dir.filePath("before.vtpar");
    doc().editMany({{0, row("E17"), dev::RawValue{0.0}}}, [] { return QStringLiteral("test"); });
    ASSERT_TRUE(window->files().saveTo(path));
    ASSERT_TRUE(window->files().openPath(path));
    QSignalSpy compared(&window->device(), &app::DeviceController::compareDialogOpened);
    window->device().compareWithDevice();
    ASSERT_TRUE(compared.wait(kWaitMs));
    const model::CompareModel *compare =
        compared.at(0).at(0).value<ui::CompareDialog *>()->compareModel();
    QStringList names;
    for (int r = 0; r < compare->rowCount(); ++r)
        names << compare->index(r, model::CompareModel::ColName).data().toString();
    EXPECT_EQ(names, QStringList{"E17"});
}

TEST_F(TrustE2E, OpenWhileConnectedKeepsTheDeviceColumnAndOffersOnlyWhatDiffers)
{
    connectSimulator();
    const QString path = dir.filePath("press.vtpar");
    ASSERT_TRUE(window->files().saveTo(path));
    // The file differs from the device in one setting.
    doc().editMany({{0, row("C1.07"), dev::RawValue{1234.0}}},
                   [] { return QStringLiteral("test"); });
    ASSERT_TRUE(window->files().saveTo(path));
    ASSERT_TRUE(window->files().openPath(path));
    EXPECT_FALSE(deviceText(0, "C1.08").isEmpty()); // the Device column stays
    EXPECT_TRUE(window->files().lastPairing().isEmpty());

    ui::WriteDialog *dialog = openWrite();
    ASSERT_NE(dialog, nullptr);
    ASSERT_EQ(dialog->table()->rowCount(), 1);
    EXPECT_EQ(dialog->table()->item(0, 1)->text(), "C1.07");
    EXPECT_NE(dialog->table()->item(0, 3)->text(), "(unknown)");
}

TEST_F(TrustE2E, NewWhileConnectedShowsTheDocumentsModulesAndNeverOffersUnknownOrSetValues)
{
    connectSimulator(3);
    ASSERT_EQ(doc().moduleCount(), 3);
    model::NewFileChoice choice;
    choice.dictionary = dictionaries().find("dma-pn-v51");
    choice.version = "51";
    choice.mode = "3";
    choice.modeRaw = 3;
    choice.modules = 1;
    window->files().newFrom(choice);
    ASSERT_EQ(doc().moduleCount(), 1); // the document's one module, not the node's three
    EXPECT_TRUE(doc().module(0).online);
    EXPECT_FALSE(window->files().lastPairing().isEmpty()); // modules 2 and 3 are named
    EXPECT_FALSE(deviceText(0, "C1.08").isEmpty());        // the device's values stay in view

    // The simulator starts from the dictionary defaults: only what the user changes is offered.
    doc().editMany({{0, row("C1.07"), dev::RawValue{1500.0}}},
                   [] { return QStringLiteral("test"); });
    ui::WriteDialog *dialog = openWrite();
    ASSERT_NE(dialog, nullptr);
    ASSERT_GE(dialog->table()->rowCount(), 1);
    for (int r = 0; r < dialog->table()->rowCount(); ++r) {
        const QString name = dialog->table()->item(r, 1)->text();
        EXPECT_NE(dialog->table()->item(r, 3)->text(), "(unknown)") << name.toStdString();
        const dev::ParamMeta *meta = row(name.toUtf8().constData());
        ASSERT_NE(meta, nullptr);
        EXPECT_EQ(meta->kind, dev::RowKind::Setting) << name.toStdString();
    }
}

TEST_F(TrustE2E, ProcessValuesAreNotSavedInAFile)
{
    connectSimulator();
    ASSERT_NO_FATAL_FAILURE(stepTo2V());
    const QString path = dir.filePath("after-step.vtpar");
    ASSERT_TRUE(window->files().saveTo(path));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_FALSE(text.contains("\"A1.01\"")) << "a bus set value was saved as a setting";
    EXPECT_TRUE(text.contains("\"E17\""));
}

TEST_F(TrustE2E, EveryValveMovingWriteIsAskedAndARefusalWritesNothing)
{
    connectSimulator();
    ASSERT_TRUE(step()->selectTarget(1, QStringLiteral("A1.01")));
    answer = false;
    step()->enableBusSetValue();
    ASSERT_EQ(asked.size(), 1);
    EXPECT_TRUE(asked[0][0].contains("E17")) << asked[0][0].toStdString();
    step()->setStepValue(2.0);
    step()->writeStep();
    ASSERT_EQ(asked.size(), 2);
    EXPECT_TRUE(asked[1][0].contains("A1.01")) << asked[1][0].toStdString();
    EXPECT_TRUE(asked[1][0].contains("2.000 V")) << asked[1][0].toStdString();
    EXPECT_FALSE(step()->isBusy());
    EXPECT_EQ(storedRaw(simModule(), *row("A1.01")), 0.0);
    EXPECT_NE(storedRaw(simModule(), *row("E17")), 2.0);

    // Write Changes of E17 (the set-value source) asks once more, naming it.
    doc().editMany({{0, row("E17"), dev::RawValue{2.0}}}, [] { return QStringLiteral("test"); });
    ui::WriteDialog *dialog = openWrite();
    ASSERT_NE(dialog, nullptr);
    dialog->confirm();
    ASSERT_EQ(asked.size(), 3);
    EXPECT_TRUE(asked[2][0].contains("E17"));
    EXPECT_NE(storedRaw(simModule(), *row("E17")), 2.0);
}

TEST_F(TrustE2E, AnArmedStepAsksOnceUntilDisconnect)
{
    connectSimulator();
    ASSERT_NO_FATAL_FAILURE(stepTo2V()); // E17 and the step: two questions
    ASSERT_EQ(asked.size(), 2);
    step()->setArmed(true);
    ASSERT_EQ(asked.size(), 3);
    EXPECT_TRUE(step()->isArmed());
    QSignalSpy written(step(), &ui::StepControl::written);
    step()->setStepValue(1.0);
    step()->writeStep();
    ASSERT_TRUE(written.wait(kWaitMs));
    EXPECT_EQ(asked.size(), 3); // armed: not asked again
    EXPECT_EQ(storedRaw(simModule(), *row("A1.01")), 1000.0);

    answer = false; // disconnect without putting back
    window->device().disconnectFromDevice();
    EXPECT_FALSE(step()->isArmed());
}

TEST_F(TrustE2E, DisconnectOffersToPutBackWhatTheToolChanged)
{
    connectSimulator();
    ASSERT_NE(storedRaw(simModule(), *row("E17")), 2.0);
    ASSERT_NO_FATAL_FAILURE(stepTo2V());
    ASSERT_EQ(window->workspace().actuatorLedger().changes().size(), 2u);

    const qsizetype before = asked.size();
    QSignalSpy disconnected(&window->workspace(), &app::Workspace::disconnected);
    window->device().disconnectFromDevice();
    ASSERT_TRUE(disconnected.count() == 1 || disconnected.wait(kWaitMs));
    ASSERT_EQ(asked.size(), before + 1);
    EXPECT_EQ(asked.back().size(), 2);
    EXPECT_TRUE(window->device().lastRestore().contains("A1.01"))
        << window->device().lastRestore().toStdString();
    EXPECT_TRUE(window->device().lastRestore().contains("E17"))
        << window->device().lastRestore().toStdString();
    EXPECT_FALSE(window->device().lastRestore().contains("Not put back"))
        << window->device().lastRestore().toStdString();
}

TEST_F(TrustE2E, QuittingWithAStepActiveAsksToPutItBack)
{
    connectSimulator();
    ASSERT_NO_FATAL_FAILURE(stepTo2V());
    const qsizetype before = asked.size();
    answer = true;
    QSignalSpy disconnected(&window->workspace(), &app::Workspace::disconnected);
    window->close();
    ASSERT_TRUE(disconnected.count() == 1 || disconnected.wait(kWaitMs));
    EXPECT_EQ(asked.size(), before + 1);
    EXPECT_TRUE(window->device().lastRestore().startsWith("Put back"))
        << window->device().lastRestore().toStdString();
}

TEST_F(TrustE2E, StoppingTheMonitorOffersToPutTheStepBack)
{
    connectSimulator();
    auto *run = window->monitor()->findChild<QPushButton *>(QStringLiteral("monitorRun"));
    ASSERT_NE(run, nullptr);
    run->click(); // start
    ASSERT_NO_FATAL_FAILURE(stepTo2V());
    const qsizetype before = asked.size();
    run->click(); // stop: the end of the test
    ASSERT_EQ(asked.size(), before + 1);
    ASSERT_TRUE(waitUntil([&] { return window->workspace().actuatorLedger().empty(); }));
    EXPECT_EQ(storedRaw(simModule(), *row("A1.01")), 0.0);
    EXPECT_TRUE(window->workspace().isConnected());
}

TEST_F(TrustE2E, AReconnectMakesEveryDeviceValueNotCurrentUntilRead)
{
    connectSimulator();
    EXPECT_TRUE(doc().deviceCurrent(0, row("C1.07")));
    window->device().disconnectFromDevice();
    EXPECT_FALSE(doc().deviceCurrent(0, row("C1.07")));
    EXPECT_TRUE(doc().value(0, row("C1.07"), model::Layer::Device)); // still shown, greyed
    const QModelIndex device = window->editor()->treeModel()->indexOf(
        0, row("C1.07"), model::ParameterTreeModel::ColDevice);
    EXPECT_TRUE(device.data(Qt::ToolTipRole).toString().contains("before the connection"))
        << device.data(Qt::ToolTipRole).toString().toStdString();
    connectSimulator();
    EXPECT_TRUE(doc().deviceCurrent(0, row("C1.07")));
}

} // namespace
} // namespace vt::test
