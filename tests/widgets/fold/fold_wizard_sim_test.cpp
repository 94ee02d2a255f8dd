// The fold wizard on a simulated node : the scan finds the modules,
// Apply writes addresses and options and the closing scan confirms them; the test bench gets
// every module's decoded CMD 15 answer over the node image with TADR toggling.
#include "actuator_answer.h"
#include "dict/dictionary_loader.h"
#include "model/session/connection.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"
#include "sim_rig.h"
#include "widgets/fold/fold_apply_page.h"
#include "widgets/fold/fold_bench_page.h"
#include "widgets/fold/fold_check_page.h"
#include "widgets/fold/fold_modules_page.h"
#include "widgets/fold/fold_wizard.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

using test::kWaitMs;
using test::openSim;
using test::waitUntil;

void nextTo(FoldWizard &wizard, int id)
{
    while (wizard.currentId() != id) {
        const int before = wizard.currentId();
        wizard.next();
        if (wizard.currentId() == before) {
            ADD_FAILURE() << "stuck on page " << before;
            return;
        }
    }
}

// SimSpec "dma-pn-v51", 3 modules, Modbus TCP; the modules start on E22 = 4, 5, 6.
TEST(FoldWizardSim, ScanApplyAndVerify)
{
    test::ActuatorAnswer yes; // the Apply is asked first
    auto c = openSim({"dma-pn-v51", 3, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    dev::sim::HcsNode &node = *c->simEndpoint()->node();
    for (std::size_t i = 0; i < 3; ++i)
        node.module(i).setAddress(static_cast<std::uint8_t>(4 + i));

    FoldWizard wizard(*dev::builtinDictionaries(), c->connection.get());
    wizard.show();
    wizard.restart();
    wizard.currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pn"))->click();
    nextTo(wizard, FoldWizard::ModulesPageId);
    auto *modules = static_cast<FoldModulesPage *>(wizard.currentPage());
    QSignalSpy scanned(modules, &FoldModulesPage::scanFinished);
    modules->findChild<QAbstractButton *>(QStringLiteral("scan"))->click();
    ASSERT_TRUE(scanned.wait(kWaitMs));
    EXPECT_EQ(scanned.front().front().toInt(), 3);
    ASSERT_EQ(wizard.plan().modules.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(wizard.plan().modules[i].version, 51);
        EXPECT_EQ(wizard.plan().modules[i].address, static_cast<int>(4 + i));
    }
    EXPECT_EQ(wizard.foundAddresses(), (std::vector<int>{4, 5, 6}));

    nextTo(wizard, FoldWizard::AddressPageId);
    wizard.currentPage()
        ->findChild<QAbstractButton *>(QStringLiteral("numberLeftToRight"))
        ->click();
    for (model::FoldModule &m : wizard.editPlan().modules) {
        m.options.e17 = 2;
        m.options.e23 = 30;
    }
    nextTo(wizard, FoldWizard::ApplyPageId);
    auto *apply = static_cast<FoldApplyPage *>(wizard.currentPage());
    QSignalSpy applied(apply, &FoldApplyPage::applyFinished);
    apply->findChild<QAbstractButton *>(QStringLiteral("apply"))->click();
    ASSERT_EQ(yes.asked.size(), 1);
    EXPECT_EQ(yes.asked[0].size(), 3) << "one line per module";
    EXPECT_FALSE(wizard.button(QWizard::NextButton)->isEnabled()); // while writing
    ASSERT_TRUE(applied.wait(kWaitMs));
    EXPECT_TRUE(applied.front().front().toBool());
    EXPECT_TRUE(wizard.button(QWizard::NextButton)->isEnabled());
    auto *table = apply->findChild<QTableWidget *>(QStringLiteral("applyResults"));
    for (std::size_t i = 0; i < 3; ++i) {
        dev::sim::HcsModule &m = node.module(i);
        EXPECT_EQ(m.address(), i + 1);
        EXPECT_EQ(m.storage().raw(*m.dictionary().find("E17")->id), 2);
        EXPECT_EQ(m.storage().raw(*m.dictionary().find("E23")->id), 30);
        ASSERT_TRUE(apply->job()->modules()[i].found.has_value());
        EXPECT_TRUE(*apply->job()->modules()[i].found);
        EXPECT_FALSE(table->item(static_cast<int>(i), 2)->text().isEmpty());
    }
}

// SimSpec "dma-pn-v51", 3 modules, node image: the bench page decodes each module's answer.
TEST(FoldWizardSim, BenchShowsEveryModulesAnswer)
{
    auto c = openSim({"dma-pn-v51", 3, "node-image", {}, {}});
    ASSERT_TRUE(c);
    FoldWizard wizard(*dev::builtinDictionaries(), c->connection.get());
    wizard.show();
    wizard.restart();
    wizard.currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pn"))->click();
    nextTo(wizard, FoldWizard::BenchPageId);
    auto *page = static_cast<FoldBenchPage *>(wizard.currentPage());
    ASSERT_TRUE(page->findChild<QAbstractButton *>(QStringLiteral("startBench"))->isEnabled());
    ASSERT_TRUE(page->startBench());
    ASSERT_TRUE(page->bench());
    EXPECT_TRUE(waitUntil(
        [&] {
            for (const model::BenchModule &m : page->bench()->modules())
                if (m.answers < 2)
                    return false;
            return true;
        },
        kWaitMs));
    page->stopBench();
    auto *table = page->findChild<QTableWidget *>(QStringLiteral("bench"));
    ASSERT_EQ(table->rowCount(), 3);
    for (int row = 0; row < 3; ++row) {
        EXPECT_TRUE(table->item(row, 4)->text().startsWith(QStringLiteral("0x")))
            << row;                                          // status word
        EXPECT_FALSE(table->item(row, 5)->text().isEmpty()); // VALUE1 in
        EXPECT_FALSE(table->item(row, 7)->text().isEmpty()); // TADRs
    }
    EXPECT_EQ(page->bench()->counters().exceptions, 0u);
    EXPECT_GT(page->bench()->lastTadr(), 1);

    // Disconnecting while telegrams are on the wire drops the bench before the session goes.
    ASSERT_TRUE(page->startBench());
    wizard.setConnection(nullptr);
    EXPECT_FALSE(page->bench());
    EXPECT_FALSE(page->findChild<QAbstractButton *>(QStringLiteral("startBench"))->isEnabled());
    c.reset();
    test::spinFor(20); // callbacks of the dropped bench, if any were left, would run now
}

} // namespace
} // namespace vt::ui

namespace vt::ui {
namespace {

using test::kWaitMs;
using test::openSim;
using test::waitUntil;

// Point-to-point guidance: "connect the cable to module 2, then Next".
TEST(FoldWizardSim, PointToPointGuidesModuleByModule)
{
    test::ActuatorAnswer yes; // each module's Apply is asked first
    auto c = openSim({"dma-pn-v51", 1, "modbus-rtu", {}, {}});
    ASSERT_TRUE(c);
    FoldWizard wizard(*dev::builtinDictionaries(), c->connection.get());
    wizard.show();
    wizard.restart();
    wizard.currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pn"))->click();
    nextTo(wizard, FoldWizard::ModulesPageId);
    wizard.currentPage()->findChild<QSpinBox *>(QStringLiteral("moduleCount"))->setValue(2);
    nextTo(wizard, FoldWizard::ApplyPageId);
    auto *apply = static_cast<FoldApplyPage *>(wizard.currentPage());
    apply->findChild<QCheckBox *>(QStringLiteral("pointToPoint"))->setChecked(true);
    auto *guide = apply->findChild<QLabel *>(QStringLiteral("guide"));
    EXPECT_TRUE(guide->text().contains(QStringLiteral("module 1")));
    QSignalSpy applied(apply, &FoldApplyPage::applyFinished);
    wizard.next(); // applies to module 1 and stays
    ASSERT_TRUE(applied.wait(kWaitMs));
    EXPECT_TRUE(applied.front().front().toBool());
    EXPECT_EQ(wizard.currentId(), FoldWizard::ApplyPageId);
    EXPECT_TRUE(guide->text().contains(QStringLiteral("module 2")));
    wizard.next(); // the cable is on module 2 now
    ASSERT_TRUE(applied.wait(kWaitMs));
    EXPECT_TRUE(applied.back().front().toBool());
    dev::sim::HcsModule &m = c->simModule(0);
    EXPECT_EQ(m.storage().raw(*m.dictionary().find("E22")->id), 2);
    wizard.next();
    EXPECT_EQ(wizard.currentId(), FoldWizard::PlcPageId);
}

// The wizard reads the node (version and mode of every module) before its first page, and the
// check page flags a plan that does not match it: here a plan of three V13 modules in mode 1 on
// a node whose three modules run V51 in mode 3, and one planned address nobody answers at.
TEST(FoldWizardSim, TheCheckPageFlagsAPlanThatDoesNotMatchTheNode)
{
    auto c = openSim({"dma-pn-v51", 2, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    FoldWizard wizard(*dev::builtinDictionaries(), c->connection.get());
    bool read = false;
    wizard.readNode([&] { read = true; });
    ASSERT_TRUE(waitUntil([&] { return read; }, kWaitMs));
    ASSERT_TRUE(wizard.nodeRead());
    ASSERT_EQ(wizard.nodeModules().size(), 2u);
    EXPECT_EQ(wizard.nodeModules()[0], (model::FoldNodeModule{1, 51, 3}));

    wizard.setPlan(model::defaultFoldPlan(model::FoldNode::DmaProfinet, 3)); // V13, mode 1
    wizard.show();
    wizard.restart();
    wizard.currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pn"))->click();
    nextTo(wizard, FoldWizard::CheckPageId);
    auto *check = static_cast<FoldCheckPage *>(wizard.currentPage());
    std::vector<model::FoldFinding> mismatches;
    for (const model::FoldFinding &f : check->findings())
        if (f.code == model::FoldCheckCode::NodeMismatch)
            mismatches.push_back(f);
    ASSERT_EQ(mismatches.size(), 3u);
    EXPECT_EQ(model::foldFindingText(mismatches[0]),
              "Module 1 (address 1) is planned as V13 in mode 1, but the connected node's module "
              "at that address runs V51 in mode 3. The plan's options and the PLC image would "
              "not fit it; scan the node or change the plan.");
    EXPECT_EQ(model::foldFindingText(mismatches[2]),
              "Module 3 (address 3) is planned, but no module of the connected node answers at "
              "that address.");
    EXPECT_TRUE(check->isComplete()); // warnings: the plan may be for the node to come

    // A plan that matches the node has no such finding.
    model::FoldPlan matching = model::defaultFoldPlan(model::FoldNode::DmaProfinet, 2);
    for (model::FoldModule &m : matching.modules) {
        m.version = 51;
        m.mode = 3;
    }
    EXPECT_TRUE(model::checkPlanAgainstNode(matching, wizard.nodeModules()).empty());
}

// Opened on a connected node, the wizard starts from the node as read: the Modules page shows
// each module's real version and mode (V51, mode 3 here), not the default plan (V13, mode 1);
// a plan changed afterwards is flagged on the check page.
TEST(FoldWizardSim, OpensOnTheConnectedNodesRealModules)
{
    auto c = openSim({"dma-pn-v51", 3, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    dev::sim::HcsNode &node = *c->simEndpoint()->node();
    node.module(2).setAddress(5); // addresses 1, 2, 5: the plan takes them as they are
    FoldWizard wizard(*dev::builtinDictionaries(), c->connection.get());
    bool read = false;
    wizard.readNode([&] { read = true; });
    ASSERT_TRUE(waitUntil([&] { return read; }, kWaitMs));
    ASSERT_TRUE(wizard.nodeRead());
    ASSERT_EQ(wizard.nodeModules().size(), 3u);

    EXPECT_EQ(wizard.plan().node, model::FoldNode::DmaProfinet);
    ASSERT_EQ(wizard.plan().modules.size(), 3u);
    const int addresses[] = {1, 2, 5};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(wizard.plan().modules[i].version, 51) << i;
        EXPECT_EQ(wizard.plan().modules[i].mode, 3) << i;
        EXPECT_EQ(wizard.plan().modules[i].address, addresses[i]) << i;
    }
    EXPECT_EQ(wizard.foundAddresses(), (std::vector<int>{1, 2, 5}));

    wizard.show();
    wizard.restart();
    nextTo(wizard, FoldWizard::ModulesPageId);
    auto *table = wizard.currentPage()->findChild<QTableWidget *>();
    ASSERT_NE(table, nullptr);
    ASSERT_EQ(table->rowCount(), 3);
    for (int row = 0; row < 3; ++row) {
        auto *version = qobject_cast<QComboBox *>(table->cellWidget(row, 1));
        auto *mode = qobject_cast<QComboBox *>(table->cellWidget(row, 2));
        ASSERT_TRUE(version && mode);
        EXPECT_EQ(version->currentData().toInt(), 51) << row;
        EXPECT_EQ(version->currentText(), "V51");
        EXPECT_EQ(mode->currentData().toInt(), 3) << row;
        EXPECT_TRUE(mode->currentText().startsWith("Mode 3")) << mode->currentText().toStdString();
    }
    nextTo(wizard, FoldWizard::CheckPageId);
    auto *check = static_cast<FoldCheckPage *>(wizard.currentPage());
    auto mismatches = [&] {
        int n = 0;
        for (const model::FoldFinding &f : check->findings())
            n += f.code == model::FoldCheckCode::NodeMismatch ? 1 : 0;
        return n;
    };
    EXPECT_EQ(mismatches(), 0); // the plan is the node

    // A plan that differs from the node (mode 4 on module 2, as a plan file may say) is flagged.
    model::FoldPlan changed = wizard.plan();
    changed.modules[1].mode = 4;
    wizard.setPlan(changed);
    nextTo(wizard, FoldWizard::CheckPageId);
    check = static_cast<FoldCheckPage *>(wizard.currentPage());
    EXPECT_EQ(mismatches(), 1);
}

} // namespace
} // namespace vt::ui
