// The fold wizard offline: pages in order, the check page blocks Next on the manuals'
// errors (duplicate E22, six DMA modules on CMD 15, SNUM mismatch) and shows the finding; the
// plan file round-trips through Save plan / openPlan; the PLC sheet exports.
#include "dict/dictionary_loader.h"
#include "widgets/fold/fold_address_page.h"
#include "widgets/fold/fold_check_page.h"
#include "widgets/fold/fold_modules_page.h"
#include "widgets/fold/fold_plc_page.h"
#include "widgets/fold/fold_wizard.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QCoreApplication>
#include <QFile>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

struct Offline
{
    FoldWizard wizard{*dev::builtinDictionaries(), nullptr};

    Offline()
    {
        wizard.show();
        wizard.restart();
    }
    bool nextEnabled() { return wizard.button(QWizard::NextButton)->isEnabled(); }
    void nextTo(int id)
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
    void chooseNode(const char *key)
    {
        ASSERT_EQ(wizard.currentId(), FoldWizard::NodePageId);
        auto *button = wizard.currentPage()->findChild<QRadioButton *>(QString::fromLatin1(key));
        ASSERT_TRUE(button);
        button->click();
    }
    std::vector<model::FoldCheckCode> shownCodes()
    {
        std::vector<model::FoldCheckCode> codes;
        auto *tree = wizard.page(FoldWizard::CheckPageId)
                         ->findChild<QTreeWidget *>(QStringLiteral("findings"));
        for (int i = 0; tree && i < tree->topLevelItemCount(); ++i) {
            EXPECT_FALSE(tree->topLevelItem(i)->text(2).isEmpty());
            codes.push_back(static_cast<model::FoldCheckCode>(
                tree->topLevelItem(i)->data(0, Qt::UserRole).toInt()));
        }
        return codes;
    }
    bool shows(model::FoldCheckCode code)
    {
        const auto codes = shownCodes();
        return std::find(codes.begin(), codes.end(), code) != codes.end();
    }
};

TEST(FoldWizard, PagesInOrderAndACleanPlanPasses)
{
    Offline w;
    w.chooseNode("dma-pn");
    w.nextTo(FoldWizard::CheckPageId);
    EXPECT_EQ(w.wizard.plan().node, model::FoldNode::DmaProfinet);
    EXPECT_TRUE(w.nextEnabled());
    EXPECT_FALSE(
        model::hasErrors(static_cast<FoldCheckPage *>(w.wizard.currentPage())->findings()));
    w.nextTo(FoldWizard::ApplyPageId); // offline: skipped with a sentence, Next stays enabled
    EXPECT_TRUE(w.nextEnabled());
    w.nextTo(FoldWizard::PlcPageId);
    auto *plc = static_cast<FoldPlcPage *>(w.wizard.currentPage());
    EXPECT_TRUE(plc->sheetHtml().contains(QStringLiteral("GSDML"))); // DMA Profinet manual §4.5.4
    w.nextTo(FoldWizard::BenchPageId);
    EXPECT_TRUE(w.wizard.page(FoldWizard::BenchPageId)
                    ->findChild<QAbstractButton *>(QStringLiteral("startBench")));
    EXPECT_FALSE(w.wizard.page(FoldWizard::BenchPageId)
                     ->findChild<QAbstractButton *>(QStringLiteral("startBench"))
                     ->isEnabled());
    // It says why it cannot run and what to connect.
    auto *intro =
        w.wizard.page(FoldWizard::BenchPageId)->findChild<QLabel *>(QStringLiteral("intro"));
    ASSERT_TRUE(intro);
    EXPECT_TRUE(intro->text().contains(QStringLiteral("no node is connected")))
        << intro->text().toStdString();
    EXPECT_TRUE(intro->text().contains(QStringLiteral("node-image")));
    EXPECT_TRUE(intro->text().contains(QStringLiteral("Device ▸ Connect")));
}

// DMA Profinet manual §4.1: every module needs its own E22.
TEST(FoldWizard, DuplicateE22BlocksNext)
{
    Offline w;
    w.chooseNode("dma-pb");
    w.nextTo(FoldWizard::AddressPageId);
    auto *table = w.wizard.currentPage()->findChild<QTableWidget *>(QStringLiteral("addresses"));
    ASSERT_TRUE(table);
    ASSERT_EQ(table->rowCount(), 3);
    auto *second = qobject_cast<QSpinBox *>(table->cellWidget(1, 1));
    ASSERT_TRUE(second);
    second->setValue(1);
    EXPECT_EQ(w.wizard.plan().modules[1].address, 1);
    w.nextTo(FoldWizard::CheckPageId);
    EXPECT_FALSE(w.nextEnabled());
    EXPECT_TRUE(w.shows(model::FoldCheckCode::DuplicateAddress));
    w.wizard.next(); // refused
    EXPECT_EQ(w.wizard.currentId(), FoldWizard::CheckPageId);

    // Back to the addresses, number them again: the error goes.
    w.wizard.back();
    w.wizard.back();
    ASSERT_EQ(w.wizard.currentId(), FoldWizard::AddressPageId);
    w.wizard.currentPage()
        ->findChild<QAbstractButton *>(QStringLiteral("numberLeftToRight"))
        ->click();
    w.nextTo(FoldWizard::CheckPageId);
    EXPECT_TRUE(w.nextEnabled());
    EXPECT_FALSE(w.shows(model::FoldCheckCode::DuplicateAddress));
}

// DMA manuals §1.5: CMD 15 reaches E22 = 1..5 only.
TEST(FoldWizard, SixDmaModulesBlockNext)
{
    Offline w;
    w.chooseNode("dma-pn");
    w.nextTo(FoldWizard::ModulesPageId);
    auto *count = w.wizard.currentPage()->findChild<QSpinBox *>(QStringLiteral("moduleCount"));
    ASSERT_TRUE(count);
    count->setValue(6);
    EXPECT_EQ(w.wizard.plan().modules.size(), 6u);
    w.nextTo(FoldWizard::CheckPageId);
    EXPECT_FALSE(w.nextEnabled());
    EXPECT_TRUE(w.shows(model::FoldCheckCode::Cmd15Limit));
}

// OPAT manual §3.1: SNUM = number of slaves; a PLC program sending another SNUM gets exception 7.
TEST(FoldWizard, SnumMismatchBlocksNext)
{
    Offline w;
    w.chooseNode("opat");
    w.nextTo(FoldWizard::CheckPageId);
    EXPECT_TRUE(w.nextEnabled());
    auto *page = w.wizard.currentPage();
    page->findChild<QCheckBox *>(QStringLiteral("hasSnum"))->setChecked(true);
    auto *snum = page->findChild<QSpinBox *>(QStringLiteral("snum"));
    snum->setValue(3); // three modules = master + 2 slaves: SNUM 2
    EXPECT_FALSE(w.nextEnabled());
    EXPECT_TRUE(w.shows(model::FoldCheckCode::SnumMismatch));
    snum->setValue(2);
    EXPECT_TRUE(w.nextEnabled());
    EXPECT_FALSE(w.shows(model::FoldCheckCode::SnumMismatch));
}

TEST(FoldWizard, OpatAddressPageSaysWhichSwitchAndTheE24Rule)
{
    Offline w;
    w.chooseNode("opat");
    w.nextTo(FoldWizard::AddressPageId);
    auto *table = w.wizard.currentPage()->findChild<QTableWidget *>(QStringLiteral("addresses"));
    ASSERT_TRUE(table);
    EXPECT_FALSE(table->cellWidget(0, 1)->isEnabled()); // the master is SADR 0
    EXPECT_TRUE(table->item(2, 2)->text().contains(QStringLiteral("rotary switch to 2")));
    w.wizard.currentPage()->findChild<QCheckBox *>(QStringLiteral("setE24"))->setChecked(true);
    w.wizard.currentPage()->findChild<QSpinBox *>(QStringLiteral("e24"))->setValue(126);
    EXPECT_EQ(w.wizard.plan().modules[0].options.e24, 126);
    const QString note =
        w.wizard.currentPage()->findChild<QLabel *>(QStringLiteral("e24Note"))->text();
    EXPECT_TRUE(note.contains(QStringLiteral("power-up")));
}

TEST(FoldWizard, SavedPlanOpensAgainAndTheSheetExports)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    Offline w;
    w.chooseNode("dma-pb");
    w.nextTo(FoldWizard::OptionsPageId);
    auto *e17 = w.wizard.currentPage()->findChild<QCheckBox *>(QStringLiteral("setE17"));
    ASSERT_TRUE(e17);
    e17->setChecked(true);
    EXPECT_TRUE(w.wizard.plan().modules[0].options.e17.has_value());
    w.nextTo(FoldWizard::PlcPageId);
    auto *plc = static_cast<FoldPlcPage *>(w.wizard.currentPage());
    const QString planPath = dir.filePath(QStringLiteral("node.vtfold"));
    EXPECT_EQ(plc->savePlan(planPath), QString());
    const QString pdf = dir.filePath(QStringLiteral("node.pdf"));
    const QString html = dir.filePath(QStringLiteral("node.html"));
    const QString csv = dir.filePath(QStringLiteral("node.csv"));
    EXPECT_EQ(plc->exportPdf(pdf), QString());
    EXPECT_EQ(plc->exportHtml(html), QString());
    EXPECT_EQ(plc->exportCsv(csv), QString());
    for (const QString &path : {pdf, html, csv})
        EXPECT_GT(QFile(path).size(), 100) << path.toStdString();
    QFile pdfFile(pdf);
    ASSERT_TRUE(pdfFile.open(QIODevice::ReadOnly));
    EXPECT_TRUE(pdfFile.read(5) == "%PDF-");

    FoldWizard other(*dev::builtinDictionaries(), nullptr);
    QString error;
    ASSERT_TRUE(other.openPlan(planPath, &error)) << error.toStdString();
    EXPECT_EQ(other.plan(), w.wizard.plan());
    EXPECT_EQ(other.planPath(), planPath);
    EXPECT_FALSE(other.openPlan(dir.filePath(QStringLiteral("missing.vtfold")), &error));
    EXPECT_FALSE(error.isEmpty());
}

TEST(FoldWizard, LanguageChangeRetranslatesEveryPage)
{
    Offline w;
    w.nextTo(FoldWizard::BenchPageId);
    const QString title = w.wizard.currentPage()->title();
    QEvent change(QEvent::LanguageChange);
    for (int id : w.wizard.pageIds())
        QCoreApplication::sendEvent(w.wizard.page(id), &change);
    EXPECT_EQ(w.wizard.currentPage()->title(),
              title); // no catalogue installed: same words, no crash
}

} // namespace
} // namespace vt::ui
