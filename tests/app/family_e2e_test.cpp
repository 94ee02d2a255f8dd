// Every family and mode the manuals describe, in the main window on the built-in simulator
// (offscreen), as `valvetune --simulate FAMILY` starts it: read all; the monitor's default
// channels are the ones the family's dictionary names for the mode (docs/DICTIONARY.md "Monitor
// defaults"); after a set value step through the monitor's step line (its confirmation answered)
// they show non-zero values; the node view shows the SD7's texts; a family without an L block
// says so in the Linearisation dock.
#include "actuator_answer.h"
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "model/monitor/sample_store.h"
#include "model/monitor/set_value_step.h"
#include "model/session/connection.h"
#include "model/session/sim_endpoint.h"
#include "sim/hart_device.h"
#include "test_wait.h"
#include "widgets/curve/lcurve_editor.h"
#include "widgets/editor/node_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QAction>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidgetItem>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace vt {
namespace {

using test::kWaitMs;

struct FamilyCase
{
    const char *family;
    int mode;           // E00; 0 for the SD7 (identified without a mode)
    double stepDisplay; // the step, in the set value's display unit
    bool hasCurve;      // the family's list has an L block
};

void PrintTo(const FamilyCase &c, std::ostream *os)
{
    *os << c.family << " mode " << c.mode;
}

struct FamilyGui : ::testing::TestWithParam<FamilyCase>
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<app::MainWindow> window;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        window = std::make_unique<app::MainWindow>(settings, language);
        window->show();
    }

    // What `valvetune --simulate FAMILY` does, with the mode the Connect dialog offers.
    bool connectAndReadAll()
    {
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = GetParam().family;
        spec.sim.mode = GetParam().mode;
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        window->device().connectTo(spec);
        return read.wait(kWaitMs) && read.at(0).at(0).toBool();
    }

    // Any channel of the module's store non-zero (and a number) in the newest rows.
    static bool anyNonZero(const model::SampleStore &store)
    {
        for (qsizetype i = std::max<qsizetype>(0, store.size() - 20); i < store.size(); ++i)
            for (int c = 0; c < store.channelCount(); ++c) {
                const double v = store.valueAt(c, i);
                if (std::isfinite(v) && v != 0)
                    return true;
            }
        return false;
    }
};

TEST_P(FamilyGui, MonitorsTheFamilysDefaultChannelsAndSeesTheSetValueStep)
{
    ASSERT_TRUE(connectAndReadAll());
    const model::ModuleInfo module = window->workspace().modules().front();
    ASSERT_TRUE(module.dictionary);
    const std::string mode = module.identification.mode;
    ui::MonitorView &monitor = *window->monitor();

    // The defaults are the dictionary's, for this mode, and there are some.
    std::vector<std::string> shown;
    for (const dev::ParamMeta *row : monitor.session().channels(module.address))
        shown.push_back(row->name);
    EXPECT_FALSE(shown.empty());
    EXPECT_EQ(shown, module.dictionary->monitor.forMode(mode).channels);

    // A set value change through the step line, as a person does it: every question answered.
    test::ActuatorAnswer yes;
    ui::StepControl &step = *monitor.stepControl();
    const auto setValues = model::SetValueStep::setValueRows(*module.dictionary, mode);
    ASSERT_FALSE(setValues.empty());
    ASSERT_TRUE(step.selectTarget(module.address, QString::fromStdString(setValues.front()->name)));
    step.setStepValue(GetParam().stepDisplay);
    QSignalSpy written(&step, &ui::StepControl::written);
    // Each activation rule the module refuses for (E17 = 2; SD7 db_Local = 0, db_DeviceMode = 1;
    // ED1/SD1 and SD7 the state DEVICE_MODE_ACTIVE) is written through the offered button, then
    // the step again.
    bool stepped = false;
    for (int round = 0; round < 6 && !stepped; ++round) {
        written.clear();
        step.writeStep();
        ASSERT_TRUE(test::waitUntil([&] { return !written.isEmpty() || step.activationOffered(); },
                                    kWaitMs))
            << step.statusText().toStdString();
        if (!written.isEmpty()) {
            stepped = true;
            break;
        }
        step.enableBusSetValue();
        ASSERT_TRUE(written.wait(kWaitMs)) << step.statusText().toStdString();
        const auto activation = written.last().at(1).value<std::vector<model::WriteItem>>();
        ASSERT_TRUE(!activation.empty() && model::isOnDevice(activation.front().status))
            << step.statusText().toStdString();
        // The device takes a control word in its own time (a cycle; not before its self test
        // ends, ED1/SD1 and HART-7 manual §4.2.2 TR_1): the status word reports the state.
        if (activation.front().row->name == "db_ControlWord") {
            const dev::ParamMeta *status = module.dictionary->find("db_StatusWord");
            ASSERT_TRUE(status);
            ASSERT_TRUE(test::waitUntil(
                [&] {
                    const auto word =
                        window->workspace().deviceImage().value(module.address, status);
                    return word && dev::dsp408::stateOfStatusWord(
                                       static_cast<std::uint16_t>(dev::rawNumber(*word))) ==
                                       dev::dsp408::State::DeviceModeActive;
                },
                kWaitMs));
        }
    }
    ASSERT_TRUE(stepped) << step.statusText().toStdString();
    ASSERT_FALSE(written.isEmpty());
    const auto items = written.last().at(1).value<std::vector<model::WriteItem>>();
    ASSERT_FALSE(items.empty());
    // Written and read back (the set value is readable in every family).
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified)
        << step.statusText().toStdString();

    monitor.setRate(50);
    monitor.start();
    const model::SampleStore *store = monitor.session().store(module.address);
    ASSERT_TRUE(store);
    EXPECT_TRUE(test::waitUntil([&] { return store->size() >= 5 && anyNonZero(*store); }, kWaitMs))
        << "no channel moved; samples: " << store->size();
    monitor.pause();
}

// Families without an L block say so instead of an empty plot with another family's help.
TEST_P(FamilyGui, TheLinearisationDockSaysWhetherThereIsACurve)
{
    ASSERT_TRUE(connectAndReadAll());
    const QString none = window->curveEditor()->noCurveText();
    if (GetParam().hasCurve)
        EXPECT_TRUE(none.isEmpty()) << none.toStdString();
    else
        EXPECT_TRUE(none.contains("has no linearisation curve")) << none.toStdString();
}

INSTANTIATE_TEST_SUITE_P(
    EveryFamilyAndMode, FamilyGui,
    ::testing::Values(
        FamilyCase{"opat", 3, 1.0, true}, FamilyCase{"opat", 4, 1.0, true},
        FamilyCase{"opat", 6, 1.0, true}, FamilyCase{"opat", 8, 1.0, true},
        FamilyCase{"dma-pn-v13", 1, 1.0, true}, FamilyCase{"dma-pn-v51", 3, 1.0, true},
        FamilyCase{"dma-pn-v51", 4, 1.0, true}, FamilyCase{"dma-pb-v15", 1, 1.0, false},
        FamilyCase{"dma-pb-v22", 2, 1.0, false}, FamilyCase{"dma-pb-v32", 3, 1.0, false},
        FamilyCase{"dma-pb-v32", 4, 1.0, false}, FamilyCase{"dma-pb-v32", 6, 1.0, false},
        FamilyCase{"dma-pb-v32", 8, 1.0, false}, FamilyCase{"wandfluh-sd7", 0, 2000, false},
        FamilyCase{"wandfluh-ed1", 0, 20.0, false}),
    [](const ::testing::TestParamInfo<FamilyCase> &param) {
        std::string name =
            std::string(param.param.family) + "_mode" + std::to_string(param.param.mode);
        for (char &c : name)
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        return name;
    });

// The node view shows the SD7's own texts (HART-7 manual §5.1.10, §5.1.11, §5.1.18; delivery
// state §6.4).
TEST(FamilyGuiSd7, TheNodeViewShowsTheDeviceTexts)
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    ASSERT_TRUE(language.setLanguage("en"));
    app::MainWindow window(settings, language);
    window.show();
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "wandfluh-sd7";
    QSignalSpy read(&window.device(), &app::DeviceController::readFinished);
    window.device().connectTo(spec);
    ASSERT_TRUE(read.wait(kWaitMs));
    auto *view = window.findChild<ui::NodeView *>();
    ASSERT_TRUE(view);
    QStringList lines;
    for (QTreeWidgetItemIterator it(view); *it; ++it)
        lines.append((*it)->text(0) + ": " + (*it)->text(1));
    EXPECT_TRUE(lines.contains("Tag: WAGSD733")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("Long tag: Wandfluh AG - SD733")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("Descriptor: WAG ELECTRONIC")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("Date: 2024-03-15")) << lines.join(" | ").toStdString();
}

struct NodeWindow
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<app::MainWindow> window;

    bool open(const char *lang, const char *family)
    {
        if (!language.setLanguage(lang))
            return false;
        window = std::make_unique<app::MainWindow>(settings, language);
        window->show();
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = family;
        QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
        window->device().connectTo(spec);
        return read.wait(kWaitMs) && read.at(0).at(0).toBool();
    }
    QStringList lines() const
    {
        QStringList out;
        for (QTreeWidgetItemIterator it(window->nodeView()); *it; ++it)
            out.append((*it)->text(0) + ": " + (*it)->text(1));
        return out;
    }
    QTreeWidgetItem *module() const { return window->nodeView()->topLevelItem(0)->child(0); }
};

// The SD7's state machine (HART-7 manual §4.2.2) and where it takes its control word and set
// value from ("Device local" §5.2.5, "Device mode" §5.2.3) in the node view, each changed there
// through the confirmation, written, read back and journalled for the put-back.
TEST(FamilyGuiSd7, TheNodeViewShowsAndDrivesTheStateDeviceLocalAndDeviceMode)
{
    NodeWindow w;
    ASSERT_TRUE(w.open("en", "wandfluh-sd7"));
    dev::sim::HartDevice &sd7 = *w.window->workspace().connection()->simEndpoint()->hart();
    // Delivery state: local mode (§4.3 "active after switch on"), set value from the bus.
    EXPECT_TRUE(w.lines().contains("Device local: control word local"))
        << w.lines().join(" | ").toStdString();
    EXPECT_TRUE(w.lines().contains("Device mode: Command value from fieldbus"))
        << w.lines().join(" | ").toStdString();
    ASSERT_TRUE(test::waitUntil([&] { return w.module()->text(4).startsWith("INIT: "); }))
        << w.module()->text(4).toStdString();

    // Refused: nothing is written.
    test::ActuatorAnswer answer(false);
    emit w.window->nodeView()->valueRequested(0, "db_Local", 0);
    ASSERT_EQ(answer.asked.size(), 1);
    EXPECT_TRUE(answer.asked[0][0].contains("db_Local")) << answer.asked[0][0].toStdString();
    EXPECT_EQ(sd7.params().value("db_Local"), 1);

    // Agreed: bus mode, read back, shown.
    answer.answer = true;
    emit w.window->nodeView()->valueRequested(0, "db_Local", 0);
    ASSERT_TRUE(test::waitUntil([&] {
        return w.lines().contains("Device local: control word via fieldbus");
    })) << w.lines().join(" | ").toStdString();
    EXPECT_EQ(sd7.params().value("db_Local"), 0);

    // D + H + M: DEVICE_MODE_ACTIVE, reported back by the status word in the state column.
    emit w.window->nodeView()->controlWordRequested(0, dev::dsp408::kControlActive);
    ASSERT_EQ(answer.asked.size(), 3);
    EXPECT_TRUE(answer.asked[2][0].contains("db_ControlWord")) << answer.asked[2][0].toStdString();
    ASSERT_TRUE(test::waitUntil([&] {
        return w.module()->text(4).startsWith("DEVICE_MODE_ACTIVE: ");
    })) << w.module()->text(4).toStdString();
    EXPECT_EQ(sd7.drive().state(), dev::dsp408::State::DeviceModeActive);

    // Both writes are journalled for the put-back.
    const auto &changes = w.window->workspace().actuatorLedger().changes();
    ASSERT_TRUE(test::waitUntil([&] { return changes.size() == 2u; }));
    std::vector<std::string> rows;
    for (const auto &change : changes)
        rows.push_back(change.row->name);
    EXPECT_NE(std::find(rows.begin(), rows.end(), "db_Local"), rows.end());
    EXPECT_NE(std::find(rows.begin(), rows.end(), "db_ControlWord"), rows.end());
    answer.answer = false; // nothing is put back while the window closes
    w.window.reset();
}

// The device's identity and the ED1's capability version in the language of the UI, and again
// after a run-time switch.
TEST(FamilyGuiLanguage, IdentityAndVersionTextsFollowTheLanguage)
{
    NodeWindow sd7;
    ASSERT_TRUE(sd7.open("de", "wandfluh-sd7"));
    EXPECT_TRUE(sd7.module()->toolTip(1).contains(QStringLiteral("Geräte-ID")))
        << sd7.module()->toolTip(1).toStdString();
    EXPECT_TRUE(sd7.module()->text(2).startsWith(QStringLiteral("Gerätetyp ")))
        << sd7.module()->text(2).toStdString();
    sd7.window->findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    EXPECT_TRUE(sd7.module()->toolTip(1).contains(QStringLiteral("device id")))
        << sd7.module()->toolTip(1).toStdString();
    EXPECT_TRUE(sd7.module()->text(2).startsWith(QStringLiteral("device type ")))
        << sd7.module()->text(2).toStdString();
    sd7.window.reset();

    NodeWindow ed1;
    ASSERT_TRUE(ed1.open("de", "wandfluh-ed1"));
    EXPECT_EQ(ed1.module()->text(2), QStringLiteral("Fähigkeiten 0x00130000"));
    ed1.window->findChild<QAction *>("actionEnglish")->trigger();
    QCoreApplication::processEvents();
    EXPECT_EQ(ed1.module()->text(2), QStringLiteral("capability 0x00130000"));
}

} // namespace
} // namespace vt
