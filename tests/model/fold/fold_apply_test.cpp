// FoldApply against the built-in simulator: every module's address and options
// are written, read back, and a scan finds each module at its planned address.
#include "dict/dictionary_loader.h"
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "model/fold/fold_apply.h"
#include "model/session/connection.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"
#include "sim_rig.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>
#include <iostream>
#include <map>

namespace vt::model {
namespace {

using test::kWaitMs;
using test::openSim;
using test::waitUntil;

int stored(test::SimRig &c, std::size_t module, const char *name)
{
    dev::sim::HcsModule &m = c.simModule(module);
    return m.storage().raw(*m.dictionary().find(name)->id);
}

FoldPlan dmaPlan(std::size_t modules)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::DmaProfinet, modules);
    for (FoldModule &m : plan.modules) {
        m.version = 51;
        m.mode = 3;
        m.options.e17 = 2;  // only the bus set values (DMA Profinet manual §6, E17)
        m.options.e23 = 50; // 500 ms telegram timeout
    }
    return plan;
}

bool run(FoldApply &apply, bool whole = true, std::size_t module = 0)
{
    QSignalSpy finished(&apply, &FoldApply::finished);
    QStringList log;
    QObject::connect(&apply, &FoldApply::message, &apply,
                     [&](const QString &text) { log << text; });
    if (whole)
        apply.start();
    else
        apply.applyModule(module);
    EXPECT_TRUE(finished.wait(kWaitMs));
    const bool ok = !finished.isEmpty() && finished.front().front().toBool();
    if (!ok) // for the failure message of a test that expected success
        for (const FoldApplyModule &m : apply.modules())
            log << m.noteTexts();
    std::cerr << (ok ? "" : log.join(QLatin1Char('\n')).toStdString() + "\n");
    return ok;
}

// DMA Profinet manual §2.2 / §4.1: E22 = 1, 2, 3 from the left. The node's modules start on
// 4, 5, 6 (as from another machine); the apply renumbers them and the scan finds 1, 2, 3.
TEST(FoldApply, SetsAddressesAndOptionsOfASimulatedNode)
{
    QTemporaryDir logDir;
    AuditLog audit(QStringLiteral("valvetune"), QStringLiteral("test"), logDir.path());
    const AuditLog::Scope auditScope(audit);
    // Modules at their factory defaults (E17 = 0, E23 = 0): the plan's options are changes.
    auto c = openSim({"dma-pn-v51", 3, "modbus-tcp", {}, {}, true});
    ASSERT_TRUE(c);
    for (std::size_t i = 0; i < 3; ++i)
        c->simModule(i).setAddress(static_cast<std::uint8_t>(4 + i));

    FoldApply apply(c->access(), dmaPlan(3), {4, 5, 6});
    ASSERT_TRUE(run(apply));
    for (std::size_t i = 0; i < 3; ++i) {
        const FoldApplyModule &m = apply.modules()[i];
        EXPECT_EQ(m.state, FoldApplyState::Done)
            << m.noteTexts().join(QStringLiteral("; ")).toStdString();
        EXPECT_TRUE(m.addressWritten);
        ASSERT_TRUE(m.found.has_value());
        EXPECT_TRUE(*m.found);
        EXPECT_EQ(c->simModule(i).address(), i + 1);
        EXPECT_EQ(stored(*c, i, "E17"), 2);
        EXPECT_EQ(stored(*c, i, "E23"), 50);
        // The options verified by read back, then E22 read back at the new address.
        ASSERT_GE(m.writes.size(), 3u);
        for (const WriteItem &item : m.writes)
            EXPECT_EQ(item.status, WriteStatus::Verified)
                << item.row->name << ": " << item.reason.text().toStdString();
    }
    // Nothing answers where the modules were.
    for (int old : {4, 5, 6})
        EXPECT_TRUE(c->simEndpoint()->node()->modulesAt(static_cast<std::uint8_t>(old)).empty());
    // Every write of the apply is in the session log under the fold wizard: the addresses (E22)
    // and each module's options.
    const AuditLogContents log = readAuditLog(audit.path());
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    std::map<QString, int> rows;
    for (const AuditEntry &e : log.entries) {
        EXPECT_EQ(e.origin, QStringLiteral("fold"));
        // E22 moves the module: it is read back at the new address by the apply itself.
        if (e.row != QStringLiteral("E22")) {
            EXPECT_EQ(e.status, QStringLiteral("verified")) << e.row.toStdString();
        }
        ++rows[e.row];
    }
    EXPECT_EQ(rows[QStringLiteral("E22")], 3);
    EXPECT_EQ(rows[QStringLiteral("E17")], 3);
    EXPECT_EQ(rows[QStringLiteral("E23")], 3);
}

// Two modules swapped (2, 1): the apply parks one on a spare address so no two ever share one.
TEST(FoldApply, SwappedAddressesNeverCollide)
{
    auto c = openSim({"dma-pn-v51", 3, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    c->simEndpoint()->node()->module(0).setAddress(2);
    c->simEndpoint()->node()->module(1).setAddress(1);
    int worst = 0;
    QObject probe;
    QObject::connect(&c->session(), &Session::frameSent, &probe, [&] {
        for (std::uint8_t a = 1; a <= 32; ++a)
            worst =
                std::max(worst, static_cast<int>(c->simEndpoint()->node()->modulesAt(a).size()));
    });
    FoldApply apply(c->access(), dmaPlan(3), {2, 1, 3});
    ASSERT_TRUE(run(apply));
    EXPECT_EQ(worst, 1);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(c->simModule(i).address(), i + 1);
}

// A value outside the dictionary's range is refused before anything is sent.
TEST(FoldApply, OutOfRangeOptionIsRefusedLocally)
{
    auto c = openSim({"dma-pn-v51", 1, "modbus-tcp", {}, {}, true}); // E17 = 0, the default
    ASSERT_TRUE(c);
    FoldPlan plan = dmaPlan(1);
    plan.modules[0].options.e17 = 7; // E17 is 0..2
    FoldApply apply(c->access(), plan, {1});
    EXPECT_FALSE(run(apply));
    const FoldApplyModule &m = apply.modules()[0];
    EXPECT_EQ(m.state, FoldApplyState::Failed);
    bool refused = false;
    for (const WriteItem &item : m.writes)
        refused =
            refused || (item.row->name == "E17" && item.status == WriteStatus::RefusedLocally);
    EXPECT_TRUE(refused);
    EXPECT_EQ(stored(*c, 0, "E17"), 0);
}

// A module that is not there: the apply says so and fails instead of pretending.
TEST(FoldApply, MissingModuleFails)
{
    auto c = openSim({"dma-pn-v51", 2, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    c->session().setOptions([&] {
        SessionOptions o = c->session().options();
        o.retries = 0;
        return o;
    }());
    FoldApply apply(c->access(), dmaPlan(3), {1, 2, 3});
    EXPECT_FALSE(run(apply));
    EXPECT_EQ(apply.modules()[2].state, FoldApplyState::Failed);
    EXPECT_FALSE(apply.modules()[2].notes.empty());
}

// OPAT manual §1.4: the slaves' addresses are rotary switches. Options are written; an address
// that differs from the plan is a job for the technician, and the apply says which position.
TEST(FoldApply, OpatOptionsAndSwitchInstruction)
{
    auto c = openSim({"opat", 3, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    FoldPlan plan = defaultFoldPlan(FoldNode::Opat, 3);
    plan.modules[0].options.e28 = 1;
    plan.modules[0].options.e23 = 20;
    plan.modules[2].address = 5; // the plan wants slave 2 on switch 5
    FoldApply apply(c->access(), plan, {0, 1, 2});
    EXPECT_FALSE(run(apply));
    EXPECT_EQ(apply.modules()[0].state, FoldApplyState::Done);
    EXPECT_EQ(stored(*c, 0, "E28"), 1);
    EXPECT_EQ(stored(*c, 0, "E23"), 20);
    EXPECT_EQ(apply.modules()[2].state, FoldApplyState::Failed);
    EXPECT_TRUE(apply.modules()[2]
                    .noteTexts()
                    .join(QLatin1Char(' '))
                    .contains(QStringLiteral("rotary switch to 5")));
}

} // namespace
} // namespace vt::model

namespace vt::model {
namespace {

using test::kWaitMs;
using test::openSim;
using test::waitUntil;

// Point-to-point (one module on the service cable, unit 1 whatever its E22): the technician
// moves the cable and each module gets its E22, read back through the line's unit.
TEST(FoldApply, PointToPointModuleByModule)
{
    auto c = openSim({"dma-pn-v51", 1, "modbus-rtu", {}, {}});
    ASSERT_TRUE(c);
    FoldApply apply(c->access(), dmaPlan(2), {1, 1});
    ASSERT_TRUE(run(apply, false, 0));
    EXPECT_EQ(stored(*c, 0, "E22"), 1);
    // "Connect the cable to module 2": the simulator's one module stands in for it.
    ASSERT_TRUE(run(apply, false, 1));
    EXPECT_EQ(stored(*c, 0, "E22"), 2);
    EXPECT_EQ(stored(*c, 0, "E17"), 2);
    EXPECT_TRUE(apply.modules()[1].addressWritten);
    EXPECT_EQ(apply.modules()[0].state, FoldApplyState::Done);
    EXPECT_EQ(apply.modules()[1].state, FoldApplyState::Done);
}

} // namespace
} // namespace vt::model
