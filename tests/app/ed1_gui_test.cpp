// The Wandfluh ED1/SD1 in the GUI on the built-in simulator, offscreen, as `valvetune --simulate
// wandfluh-ed1` starts it: it connects over the PROFIBUS image (raw and through a gateway's Modbus
// TCP registers), identifies by db_Capability (ED1/SD1 manual §4.8.7), reads every parameter by
// IND/PNU and shows the values; the node view shows the device state the status word reports
// (§4.2.2, §4.8.3), and a state chosen there is asked first, then written as the PZD control word
// (§4.8.2) and journalled for the put-back.
#include "actuator_answer.h"
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "dsp408/state_machine.h"
#include "model/params/parameter_tree_model.h"
#include "sim/dsp408_device.h"
#include "sim_rig.h"
#include "widgets/editor/node_view.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QSignalSpy>
#include <QTemporaryDir>

namespace vt::test {
namespace {

using app::MainWindow;

struct Ed1Gui : ::testing::TestWithParam<dev::LinkProtocol>
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<MainWindow> window;
    ActuatorAnswer answer;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        window = std::make_unique<MainWindow>(settings, language);
        window->show();
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = "wandfluh-ed1";
        spec.sim.protocol = GetParam();
        window->device().connectTo(spec); // identifies, then reads all
        ASSERT_TRUE(read.wait(kWaitMs));
        ASSERT_TRUE(read.at(0).at(0).toBool());
    }
    void TearDown() override
    {
        answer.answer = false; // nothing is put back while the window closes
        window.reset();
    }

    model::ParameterDocument &doc() { return window->workspace().document(); }
    dev::sim::Dsp408Device &device()
    {
        return *window->workspace().connection()->simEndpoint()->ed1();
    }
    QString shown(const char *name, int column = model::ParameterTreeModel::ColDevice)
    {
        const dev::ParamMeta *r = doc().module(0).dictionary->find(name);
        return window->editor()->treeModel()->indexOf(0, r, column).data().toString();
    }
};

TEST_P(Ed1Gui, ConnectsReadsAllAndShowsTheValues)
{
    ASSERT_EQ(doc().moduleCount(), 1);
    EXPECT_EQ(doc().module(0).dictionary->family, "wandfluh-ed1");
    EXPECT_TRUE(doc().module(0).online);
    // §4.4 defaults as the simulated card holds them, in display units.
    EXPECT_EQ(shown("dpc_PropFact1"), QStringLiteral("20"));
    EXPECT_EQ(shown("db_ControlMode"), QStringLiteral("Position control axis"));
    EXPECT_EQ(shown("dpc_window_ThresholdVal"), QStringLiteral("1.563 mm"));
    EXPECT_TRUE(shown("db_Capability").startsWith(QStringLiteral("Hydraulic Drive")));
    // The connection names the link protocol.
    EXPECT_TRUE(window->workspace().connection()->displayText().contains(
        QLatin1String(dev::key(GetParam()))));
}

TEST_P(Ed1Gui, TheNodeViewShowsTheStateAndAChosenStateIsAskedWrittenAndJournalled)
{
    // The card runs its self test first (NOT_READY, then TR_1 to INIT); the display values'
    // live poll brings the status word to the node view.
    ASSERT_TRUE(waitUntil([&] { return device().state() == dev::dsp408::State::Init; }));
    ASSERT_TRUE(waitUntil([&] {
        return model::stateWordText(doc(), 0).startsWith(QStringLiteral("INIT: "));
    })) << model::stateWordText(doc(), 0).toStdString();
    EXPECT_TRUE(
        window->nodeView()->topLevelItem(0)->child(0)->text(4).startsWith(QStringLiteral("INIT")));

    // Refused: nothing is written.
    answer.answer = false;
    emit window->nodeView()->controlWordRequested(0, dev::dsp408::kControlActive);
    ASSERT_EQ(answer.asked.size(), 1);
    EXPECT_TRUE(answer.asked[0][0].contains(QStringLiteral("db_ControlWord")))
        << answer.asked[0][0].toStdString();
    EXPECT_EQ(device().state(), dev::dsp408::State::Init);

    // Agreed: D + H + M → DEVICE_MODE_ACTIVE (§4.2.2 TR_2, TR_3, TR_4).
    answer.answer = true;
    emit window->nodeView()->controlWordRequested(0, dev::dsp408::kControlActive);
    ASSERT_EQ(answer.asked.size(), 2);
    ASSERT_TRUE(
        waitUntil([&] { return device().state() == dev::dsp408::State::DeviceModeActive; }));
    const auto &changes = window->workspace().actuatorLedger().changes();
    ASSERT_TRUE(waitUntil([&] { return changes.size() == 1u; }));
    EXPECT_EQ(changes.front().row->name, "db_ControlWord");
    // The actual value (a live value of block dpc) follows in the editor as the axis moves.
    const dev::ParamMeta *setpoint = doc().module(0).dictionary->find("dpc_SetpointVal");
    std::optional<model::Outcome> written;
    window->workspace().connection()->access().write(doc().module(0).address, *setpoint, 512.0,
                                                     model::Priority::User, std::nullopt,
                                                     [&](const model::Outcome &o) { written = o; });
    ASSERT_TRUE(waitFor(written));
    ASSERT_EQ(written->status, model::OutcomeStatus::Ok);
    ASSERT_TRUE(waitUntil([&] { return shown("dpc_ActualVal") != QStringLiteral("0.000 mm"); }))
        << shown("dpc_ActualVal").toStdString();
    // Back to INIT, as the put-back on disconnect would offer.
    emit window->nodeView()->controlWordRequested(0, dev::dsp408::kControlInit);
    ASSERT_TRUE(waitUntil([&] { return device().state() == dev::dsp408::State::Init; }));
}

// The monitor's step drives dpc_SetpointVal through the PZD, but only DEVICE_MODE_ACTIVE makes
// the set value act (ED1/SD1 manual §4.2.2): in INIT the step is refused with the manual's words
// and a confirmed switch is offered; a typed 10 mm is said to be sent as the 9.961 mm the raw
// grid holds (0.09765625 mm per raw step).
TEST_P(Ed1Gui, TheStepChecksTheDeviceStateAndSaysTheRoundedValue)
{
    ASSERT_TRUE(waitUntil([&] { return device().state() == dev::dsp408::State::Init; }));
    ui::StepControl &step = *window->monitor()->stepControl();
    ASSERT_TRUE(step.selectTarget(doc().module(0).address, QStringLiteral("dpc_SetpointVal")));
    step.setStepValue(10.0);
    answer.answer = true;
    step.writeStep();
    ASSERT_EQ(answer.asked.size(), 1);
    EXPECT_TRUE(answer.asked[0][0].contains(QStringLiteral("9.961 mm")))
        << answer.asked[0][0].toStdString();
    EXPECT_TRUE(answer.asked[0][0].contains(
        QStringLiteral("(typed 10.000 mm, rounded to the device resolution)")))
        << answer.asked[0][0].toStdString();
    EXPECT_TRUE(
        step.statusText().contains(QStringLiteral("10.000 mm → 9.961 mm (device resolution)")))
        << step.statusText().toStdString();

    // Refused in INIT: nothing reaches the set value.
    ASSERT_TRUE(waitUntil([&] { return step.activationOffered(); }))
        << step.statusText().toStdString();
    EXPECT_TRUE(step.statusText().contains(QStringLiteral("The device is in state INIT")))
        << step.statusText().toStdString();
    EXPECT_TRUE(step.statusText().contains(QStringLiteral("Switch it to DEVICE_MODE_ACTIVE")))
        << step.statusText().toStdString();
    const dev::ParamMeta *setpoint = doc().module(0).dictionary->find("dpc_SetpointVal");
    EXPECT_EQ(device().params().value(*setpoint), 0);

    // The offered switch is asked for as the control word, then written.
    QSignalSpy written(&step, &ui::StepControl::written);
    step.enableBusSetValue();
    ASSERT_EQ(answer.asked.size(), 2);
    EXPECT_TRUE(answer.asked[1][0].contains(QStringLiteral("db_ControlWord")))
        << answer.asked[1][0].toStdString();
    ASSERT_TRUE(written.wait(kWaitMs)) << step.statusText().toStdString();
    ASSERT_TRUE(
        waitUntil([&] { return device().state() == dev::dsp408::State::DeviceModeActive; }));

    // Now the step goes through, read back, and still says it was rounded.
    written.clear();
    step.writeStep();
    ASSERT_TRUE(written.wait(kWaitMs)) << step.statusText().toStdString();
    const auto items = written.last().at(1).value<std::vector<model::WriteItem>>();
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items.front().row, setpoint);
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified)
        << step.statusText().toStdString();
    EXPECT_EQ(device().params().value(*setpoint), 102); // 9.961 mm / 0.09765625 mm
    EXPECT_TRUE(step.statusText().contains(QStringLiteral("→ 9.961 mm (device resolution)")))
        << step.statusText().toStdString();

    // The shown value of a raw step is sent as typed: nothing is said to be rounded.
    step.setStepValue(9.961);
    written.clear();
    step.writeStep();
    ASSERT_TRUE(written.wait(kWaitMs)) << step.statusText().toStdString();
    EXPECT_FALSE(answer.asked.back()[0].contains(QStringLiteral("typed")))
        << answer.asked.back()[0].toStdString();
    EXPECT_FALSE(step.statusText().contains(QStringLiteral("device resolution")))
        << step.statusText().toStdString();
}

INSTANTIATE_TEST_SUITE_P(Mappings, Ed1Gui,
                         ::testing::Values(dev::LinkProtocol::Dsp408Image,
                                           dev::LinkProtocol::Dsp408Gateway),
                         [](const auto &param) {
                             return param.param == dev::LinkProtocol::Dsp408Image
                                        ? std::string("Image")
                                        : std::string("Gateway");
                         });

} // namespace
} // namespace vt::test
