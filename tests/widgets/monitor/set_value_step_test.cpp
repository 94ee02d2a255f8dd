// The monitor's set value step: refused while E17 ≠ 2 with the manuals' reason, E17 set
// on request, then the step written through WriteJob, read back and journalled.
#include "actuator_answer.h"
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "model/monitor/set_value_step.h"
#include "sim_rig.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/monitor/step_control.h"

#include <QTemporaryDir>
#include <cmath>

namespace vt::test {
namespace {

using model::SetValueStep;

// The set values and their activation row are the dictionary's ("monitor"."set_values").
TEST(SetValueStep, OffersTheSetValuesTheFamilysDictionaryNames)
{
    auto names = [](const char *family, const char *mode) {
        QStringList out;
        for (const dev::ParamMeta *row :
             SetValueStep::setValueRows(*dictionaries().find(family), mode))
            out.append(QString::fromStdString(row->name));
        return out;
    };
    EXPECT_EQ(names("dma-pn-v51", "3"), (QStringList{"A1.01", "A2.01"}));
    EXPECT_EQ(names("opat", "3"), (QStringList{"A1.01", "A2.01"}));
    EXPECT_EQ(names("dma-pn-v13", "1"), (QStringList{"A1.01"})); // §4.5.2: A1.01 only
    // HART-7 manual §5.2.8: each control mode's command value.
    EXPECT_EQ(names("wandfluh-sd7", ""),
              (QStringList{"vpoc_CommandValue", "vprc_CommandValue", "dcol_CommandValue",
                           "dsc_CommandValue", "dpc_CommandValue", "npc_CommandValue"}));
    auto rules = [](const char *family, const char *mode) {
        QStringList out;
        for (const dev::SetValueActivation *rule :
             SetValueStep::activationRules(*dictionaries().find(family), mode))
            out.append(QString::fromStdString(rule->row) + "=" + QString::number(rule->value));
        return out;
    };
    EXPECT_EQ(rules("dma-pb-v32", "3"), (QStringList{"E17=2"}));
    // HART-7 manual §4.2.1 bus mode, §5.2.3 "1: Command value from fieldbus", §4.2.2 the state
    // DEVICE_MODE_ACTIVE read from the status word (written as control word 0x0007).
    EXPECT_EQ(rules("wandfluh-sd7", ""),
              (QStringList{"db_Local=0", "db_DeviceMode=1", "db_StatusWord=7"}));
    EXPECT_EQ(rules("wandfluh-ed1", ""),
              (QStringList{"db_Local=0", "db_DeviceMode=1", "db_StatusWord=7"}));
}

TEST(SetValueStep, RefusedWhileE17IsNotTwoThenWrittenAfterE17IsSet)
{
    // A module at its factory defaults: the commissioned simulator already has E17 = 2.
    QTemporaryDir logDir;
    model::AuditLog audit(QStringLiteral("valvetune"), QStringLiteral("test"), logDir.path());
    const model::AuditLog::Scope auditScope(audit);
    SimSetup setup;
    setup.family = "dma-pn-v51";
    setup.factory = true;
    auto rig = connectSim(setup);
    ASSERT_TRUE(rig);
    ASSERT_EQ(rig->read("E17"), 0.0); // the manual's default
    SetValueStep step(rig->connection->access(), rig->module());
    QSignalSpy refused(&step, &SetValueStep::refused);
    QSignalSpy written(&step, &SetValueStep::written);

    step.step(rig->row("A1.01"), 1000);
    ASSERT_TRUE(refused.wait(kWaitMs));
    EXPECT_TRUE(refused.front().at(1).toBool()); // needs activation
    const QString reason = refused.front().front().toString();
    EXPECT_TRUE(reason.contains("E17")) << reason.toStdString();
    EXPECT_TRUE(reason.contains("E17 = 2 is required")) << reason.toStdString();
    EXPECT_EQ(written.count(), 0);
    EXPECT_EQ(rig->read("A1.01"), 0.0); // nothing was written

    step.enableBusSetValue();
    ASSERT_TRUE(written.wait(kWaitMs));
    auto items = written.front().at(1).value<std::vector<model::WriteItem>>();
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items.front().row->name, "E17");
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified);
    EXPECT_EQ(rig->read("E17"), 2.0);

    written.clear();
    step.step(rig->row("A1.01"), 1000);
    ASSERT_TRUE(written.wait(kWaitMs));
    items = written.front().at(1).value<std::vector<model::WriteItem>>();
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items.front().row->name, "A1.01");
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified); // range-checked, read back
    ASSERT_TRUE(items.front().before);
    EXPECT_EQ(dev::rawNumber(*items.front().before), 0.0);
    EXPECT_TRUE(written.front().at(2).toBool());
    EXPECT_EQ(rig->read("A1.01"), 1000.0);
    // Both writes are in the session log under the monitor; the refused step sent nothing.
    const model::AuditLogContents log = model::readAuditLog(audit.path());
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    ASSERT_EQ(log.entries.size(), 2u);
    EXPECT_EQ(log.entries[0].row, QStringLiteral("E17"));
    EXPECT_EQ(log.entries[1].row, QStringLiteral("A1.01"));
    for (const model::AuditEntry &e : log.entries) {
        EXPECT_EQ(e.status, QStringLiteral("verified"));
        EXPECT_EQ(e.origin, QStringLiteral("monitor"));
    }
}

TEST(SetValueStep, OutOfRangeStepIsRefusedLocallyByWriteJob)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    SetValueStep step(rig->connection->access(), rig->module());
    QSignalSpy written(&step, &SetValueStep::written);
    step.enableBusSetValue();
    ASSERT_TRUE(written.wait(kWaitMs));
    written.clear();
    step.step(rig->row("A1.01"), 20000); // manual: -9999 … 9999
    ASSERT_TRUE(written.wait(kWaitMs));
    const auto items = written.front().at(1).value<std::vector<model::WriteItem>>();
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items.front().status, model::WriteStatus::RefusedLocally);
    EXPECT_EQ(rig->read("A1.01"), 0.0);
}

TEST(StepControl, StepFromTheMonitorIsJournalledAndSeenOnThePlot)
{
    ActuatorAnswer yes;
    SimSetup setup;
    setup.family = "dma-pn-v51";
    setup.factory = true; // E17 = 0: the step asks for E17 first
    auto rig = connectSim(setup);
    ASSERT_TRUE(rig);
    ui::MonitorView view;
    view.setConnection(rig->connection.get(), rig->modules);
    ui::StepControl &control = *view.stepControl();
    ASSERT_TRUE(control.selectTarget(rig->module().address, QStringLiteral("A1.01")));
    control.setStepValue(1.0);
    QSignalSpy written(&control, &ui::StepControl::written);

    control.writeStep();
    ASSERT_TRUE(waitUntil([&] { return control.activationOffered(); }, kWaitMs));
    EXPECT_TRUE(control.statusText().contains("E17")) << control.statusText().toStdString();
    EXPECT_TRUE(view.session().journal().markers().empty());

    control.enableBusSetValue();
    ASSERT_TRUE(written.wait(kWaitMs));
    ASSERT_EQ(yes.asked.size(), 2); // the step (then refused: E17 is not 2), and E17
    ASSERT_EQ(view.session().journal().markers().size(), 1u);
    EXPECT_TRUE(view.session().journal().markers().back().text.startsWith("E17 "));

    view.setRate(100);
    view.start();
    control.writeStep();
    ASSERT_TRUE(written.wait(kWaitMs));
    ASSERT_EQ(view.session().journal().markers().size(), 2u);
    EXPECT_EQ(view.session().journal().markers().back().text,
              QStringLiteral("A1.01 0.000 V → 1.000 V"));
    EXPECT_EQ(rig->read("A1.01"), 1000.0);

    // The desired value d1.10 follows the bus set value once E17 = 2.
    const model::SampleStore *store = view.session().store(rig->module().address);
    const int desired = store->channelIndex(QStringLiteral("d1.10"));
    ASSERT_GE(desired, 0);
    EXPECT_TRUE(waitUntil(
        [&] {
            return store->size() > 0 &&
                   std::abs(store->valueAt(desired, store->size() - 1) - 1.0) < 0.01;
        },
        kWaitMs));
    view.pause();
}

} // namespace
// On the commissioned simulator (E17 = 2, a position loop with its sensor) the step is asked once
// and written, and the actual value d1.11 follows it on the plot: the axis moves.
TEST(StepControl, OnTheCommissionedSimulatorTheActualValueFollowsTheStep)
{
    ActuatorAnswer yes;
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    ui::MonitorView view;
    view.setConnection(rig->connection.get(), rig->modules);
    ui::StepControl &control = *view.stepControl();
    ASSERT_TRUE(control.selectTarget(rig->module().address, QStringLiteral("A1.01")));
    control.setStepValue(2.0);
    QSignalSpy written(&control, &ui::StepControl::written);
    view.setRate(100);
    view.start();
    control.writeStep();
    ASSERT_TRUE(written.wait(kWaitMs)) << control.statusText().toStdString();
    EXPECT_EQ(yes.asked.size(), 1); // the step only: no E17 to set
    EXPECT_FALSE(control.activationOffered());
    const model::SampleStore *store = view.session().store(rig->module().address);
    const int actual = store->channelIndex(QStringLiteral("d1.11"));
    ASSERT_GE(actual, 0);
    EXPECT_TRUE(waitUntil(
        [&] {
            return store->size() > 0 &&
                   std::abs(store->valueAt(actual, store->size() - 1) - 2.0) < 0.1;
        },
        kWaitMs))
        << "d1.11 = " << (store->size() ? store->valueAt(actual, store->size() - 1) : -1.0);
    view.pause();
}

} // namespace vt::test
