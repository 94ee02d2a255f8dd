// The device image against an independent reader, across processes: valvetune-sim serves a DMA-2
// over Modbus TCP; the GUI (in this process) writes through each of its write paths — Write
// Changes, "Set E17 = 2", the monitor's step, a composed Modbus write, the put-back on
// disconnect — and after each one valvetune-cli (its own process, its own connection) reads the
// device: the editor's Device column holds what the CLI reads, every time.
#include "actuator_answer.h"
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/gui_options.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "dict/raw_value.h"
#include "sim_process.h"
#include "test_wait.h"
#include "widgets/editor/write_dialog.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace vt {
namespace {

using test::kWaitMs;

struct DeviceImageCli : ::testing::Test
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<app::MainWindow> window;
    std::unique_ptr<simtest::Sim> sim;
    QString where;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        sim = std::make_unique<simtest::Sim>(
            // --factory: E17 = 0, so "Set E17 = 2" is a change the disconnect puts back.
            QStringList{"--device", "dma-pn-v51", "--factory", "--tcp", "127.0.0.1:0"});
        where = sim->listening();
        ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim->stderrText().toStdString();
        window = std::make_unique<app::MainWindow>(settings, language);
        window->show();
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        const app::GuiOptions options =
            app::parseGuiOptions({"valvetune", "--connect", "--tcp", where});
        ASSERT_TRUE(options.connection.has_value()) << options.error.toStdString();
        window->device().connectTo(*options.connection);
        ASSERT_TRUE(read.wait(kWaitMs));
        ASSERT_TRUE(read.at(0).at(0).toBool());
    }

    model::ParameterDocument &doc() { return window->workspace().document(); }
    const dev::ParamMeta *row(const char *name) { return doc().module(0).dictionary->find(name); }

    // What valvetune-cli reads from the device now, raw, by name.
    std::map<QString, double> cliRead(const QStringList &names)
    {
        QStringList args{"get", "--tcp", where, "--json"};
        args += names;
        const auto run = simtest::run(VT_CLI_PATH, args);
        EXPECT_TRUE(run.finished);
        EXPECT_EQ(run.code, 0) << run.err.toStdString();
        std::map<QString, double> values;
        const QJsonArray array =
            QJsonDocument::fromJson(run.out.toUtf8()).object().value("values").toArray();
        for (const QJsonValue &v : array)
            values[v.toObject().value("name").toString()] = v.toObject().value("raw").toDouble();
        return values;
    }

    // The Device column (the image) equals what the CLI reads, for every named row.
    void expectImageIsDevice(const QStringList &names)
    {
        const auto device = cliRead(names);
        ASSERT_EQ(device.size(), static_cast<std::size_t>(names.size()));
        for (const QString &name : names) {
            const auto image = doc().value(0, row(name.toUtf8().constData()), model::Layer::Device);
            ASSERT_TRUE(image.has_value()) << name.toStdString();
            EXPECT_EQ(dev::rawNumber(*image), device.at(name)) << name.toStdString();
            EXPECT_TRUE(doc().deviceCurrent(0, row(name.toUtf8().constData())))
                << name.toStdString();
        }
    }
};

TEST_F(DeviceImageCli, EveryWritePathLeavesTheImageEqualToWhatTheCliReads)
{
    test::ActuatorAnswer yes;
    const QStringList rows{"C1.07", "C1.08", "E17", "A1.01"};
    expectImageIsDevice(rows); // after Read All

    // Write Changes.
    doc().editMany({{0, row("C1.07"), dev::RawValue{1234.0}}},
                   [] { return QStringLiteral("test"); });
    ui::WriteDialog *dialog = window->device().writeChanges();
    ASSERT_NE(dialog, nullptr);
    QSignalSpy written(dialog, &ui::WriteDialog::writeFinished);
    dialog->confirm();
    ASSERT_TRUE(written.wait(kWaitMs));
    expectImageIsDevice(rows);

    // "Set E17 = 2", then the monitor's step.
    ui::StepControl *step = window->monitor()->stepControl();
    ASSERT_TRUE(step->selectTarget(1, QStringLiteral("A1.01")));
    QSignalSpy stepped(step, &ui::StepControl::written);
    step->enableBusSetValue();
    ASSERT_TRUE(stepped.wait(kWaitMs));
    step->setStepValue(1.5);
    step->writeStep();
    ASSERT_TRUE(test::waitUntil([&] { return stepped.count() == 2; }));
    expectImageIsDevice(rows);

    // A Modbus FC 6 write of C1.08 composed in the inspector: read back into the image.
    ui::ComposePanel *compose = window->inspector()->composePanel();
    compose->setConfirmation([](const QString &) { return true; });
    compose->setKind(dev::inspect::ComposeKind::ModbusWrite);
    compose->setFieldText("unit", "1");
    compose->setFieldText("id", QString::number(*row("C1.08")->id));
    compose->setFieldText("value", "777");
    QSignalSpy sent(compose, &ui::ComposePanel::sendFinished);
    ASSERT_TRUE(compose->send()) << compose->sendBlockedReason().toStdString();
    ASSERT_TRUE(sent.wait(kWaitMs));
    ASSERT_TRUE(test::waitUntil([&] {
        return doc().value(0, row("C1.08"), model::Layer::Device) == dev::RawValue{777.0};
    }));
    expectImageIsDevice(rows);

    // Disconnect puts the step and E17 back; the last image is what the device holds.
    QSignalSpy disconnected(&window->workspace(), &app::Workspace::disconnected);
    window->device().disconnectFromDevice();
    ASSERT_TRUE(disconnected.count() == 1 || disconnected.wait(kWaitMs));
    const auto device = cliRead({"E17", "A1.01"});
    EXPECT_EQ(device.at("A1.01"), 0.0);
    EXPECT_NE(device.at("E17"), 2.0);
    EXPECT_EQ(dev::rawNumber(*doc().value(0, row("A1.01"), model::Layer::Device)), 0.0);
    EXPECT_EQ(dev::rawNumber(*doc().value(0, row("E17"), model::Layer::Device)), device.at("E17"));
}

} // namespace
} // namespace vt
