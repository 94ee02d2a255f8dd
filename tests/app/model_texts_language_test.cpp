// The model's own sentences go through tr() and the devices' {en, de} texts stay bilingual until
// shown: after a switch of the language a fold check finding (on the check page, too), a write
// job's refusals, a parameter edit's refusal and a module's identity read German; switching back
// restores English.
#include "app/gui/language.h"
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve.h"
#include "model/fold/fold_apply.h"
#include "model/fold/fold_check.h"
#include "model/params/parameter_document.h"
#include "model/session/write_job.h"
#include "model/text_language.h"
#include "sim_rig.h"
#include "widgets/fold/fold_wizard.h"

#include <QAbstractButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QTreeWidget>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

QString tr(const char *context, const char *text)
{
    return QCoreApplication::translate(context, text);
}

// German for the test's body; English again afterwards, whatever the test's outcome.
struct German
{
    app::Language language;
    German() { EXPECT_TRUE(language.setLanguage(QStringLiteral("de"))); }
    ~German() { language.setLanguage(QStringLiteral("en")); }
};

const model::FoldFinding *find(const std::vector<model::FoldFinding> &all,
                               model::FoldCheckCode code)
{
    const auto it = std::find_if(all.begin(), all.end(),
                                 [code](const model::FoldFinding &f) { return f.code == code; });
    return it == all.end() ? nullptr : &*it;
}

TEST(ModelTextsLanguage, FoldCheckFindingInGerman)
{
    model::FoldPlan plan = model::defaultFoldPlan(model::FoldNode::DmaProfinet, 3);
    plan.modules[2].address = 2;
    German german;
    const auto findings = model::checkFoldPlan(plan);
    const model::FoldFinding *f = find(findings, model::FoldCheckCode::DuplicateAddress);
    ASSERT_NE(f, nullptr);
    EXPECT_TRUE(model::foldFindingText(*f).startsWith(
        QStringLiteral("Module 2, 3 haben dasselbe E22 = 2: ")))
        << model::foldFindingText(*f).toStdString();
    EXPECT_EQ(model::foldSeverityText(f->severity), QStringLiteral("Fehler"));

    german.language.setLanguage(QStringLiteral("en"));
    const auto english = model::checkFoldPlan(plan);
    f = find(english, model::FoldCheckCode::DuplicateAddress);
    ASSERT_NE(f, nullptr);
    EXPECT_TRUE(
        model::foldFindingText(*f).startsWith(QStringLiteral("Modules 2, 3 share E22 = 2: ")))
        << model::foldFindingText(*f).toStdString();
}

// The check page shows the findings in the language chosen while it is open.
TEST(ModelTextsLanguage, CheckPageRerendersItsFindings)
{
    ui::FoldWizard wizard(*dev::builtinDictionaries(), nullptr);
    wizard.show();
    wizard.restart();
    wizard.currentPage()->findChild<QRadioButton *>(QStringLiteral("dma-pb"))->click();
    while (wizard.currentId() != ui::FoldWizard::CheckPageId) {
        const int before = wizard.currentId();
        wizard.next();
        ASSERT_NE(wizard.currentId(), before) << "stuck on page " << before;
    }
    auto *tree = wizard.currentPage()->findChild<QTreeWidget *>(QStringLiteral("findings"));
    ASSERT_TRUE(tree);
    ASSERT_GE(tree->topLevelItemCount(), 1); // no product number given: HCS0220.GSD assumed
    const QString english = tree->topLevelItem(0)->text(2);
    EXPECT_TRUE(english.startsWith(QStringLiteral("No product number given")))
        << english.toStdString();

    German german;
    QCoreApplication::processEvents(); // the LanguageChange events are posted to the windows
    const QString shown = tree->topLevelItem(0)->text(2);
    EXPECT_TRUE(shown.startsWith(QStringLiteral("Keine Produktnummer angegeben")))
        << shown.toStdString();
}

// The write dialog shows a job's results in the language of the moment (it is window-modal: the
// language cannot change while it is open); the device's refusal stays in both languages.
TEST(ModelTextsLanguage, WriteJobRefusalsInGerman)
{
    auto c = connectSim("dma-pn-v51");
    ASSERT_TRUE(c);
    // A copy of C1.07 with a wider range than the module takes: the device refuses (exception 3).
    dev::ParamMeta wide = *c->dictionary().find("C1.07");
    wide.max = 32000;
    std::vector<model::WriteItem> list(2);
    list[0].row = &wide;
    list[0].value = 20000.0;
    list[1].row = c->dictionary().find("d1.11"); // read only: refused before sending
    list[1].value = 5.0;
    model::WriteJob job(c->access(), c->address(), c->dictionary(), list,
                        model::AuditOrigin::Editor);
    QSignalSpy finished(&job, &model::WriteJob::finished);
    {
        German german;
        job.start();
        ASSERT_TRUE(finished.wait(kWaitMs) || finished.count() > 0);

        const model::WriteItem &refused = job.items()[0];
        ASSERT_EQ(refused.status, model::WriteStatus::Refused);
        ASSERT_TRUE(refused.deviceText.complete());
        const QString shown = model::writeReasonText(refused, model::textLanguage());
        EXPECT_EQ(shown, QString::fromStdString(refused.deviceText.de));
        EXPECT_NE(shown, QString::fromStdString(refused.deviceText.en));
        EXPECT_EQ(model::writeStatusText(refused.status),
                  tr("vt::model::WriteJob", "refused by the device"));
        EXPECT_NE(model::writeStatusText(refused.status), QStringLiteral("refused by the device"));

        const model::WriteItem &local = job.items()[1];
        ASSERT_EQ(local.status, model::WriteStatus::RefusedLocally);
        EXPECT_EQ(model::writeReasonText(local, model::textLanguage()),
                  QStringLiteral("d1.11 ist nicht beschreibbar"));
    }
    // Back in English, the same result says the device's refusal in English, and the refusal
    // the application worded while German was in force is said again in English.
    EXPECT_EQ(model::writeReasonText(job.items()[0], model::textLanguage()),
              QString::fromStdString(job.items()[0].deviceText.en));
    EXPECT_EQ(model::writeReasonText(job.items()[1], model::textLanguage()),
              QStringLiteral("d1.11 is not writable"));
}

// OPAT manual §1.4: a slave's SADR is its rotary switch. The address inside a finding is a value
// until it is shown, so it follows the language like the sentence around it.
TEST(ModelTextsLanguage, OpatAddressInAFindingFollowsTheLanguage)
{
    model::FoldPlan plan = model::defaultFoldPlan(model::FoldNode::Opat, 3);
    plan.modules[2].address = 9; // beyond the rotary switch's 1..7
    const auto findings = model::checkFoldPlan(plan);
    const model::FoldFinding *f = find(findings, model::FoldCheckCode::AddressOutOfRange);
    ASSERT_NE(f, nullptr);
    EXPECT_TRUE(model::foldFindingText(*f).contains(QStringLiteral("SADR 9 (rotary switch 9)")))
        << model::foldFindingText(*f).toStdString();
    {
        German german;
        EXPECT_TRUE(model::foldFindingText(*f).contains(QStringLiteral("SADR 9 (Drehschalter 9)")))
            << model::foldFindingText(*f).toStdString();
        EXPECT_EQ(model::foldAddressText(plan.node, plan.modules[0]),
                  QStringLiteral("SADR 0 (Master)"));
    }
    EXPECT_EQ(model::foldAddressText(plan.node, plan.modules[0]),
              QStringLiteral("SADR 0 (master)"));
}

// A fold apply's notes stay on the apply page: made in German, they are said in English after a
// switch (OPAT manual §1.4: the rotary switch instruction).
TEST(ModelTextsLanguage, FoldApplyNotesFollowTheLanguage)
{
    auto c = openSim({"opat", 3, "modbus-tcp", {}, {}});
    ASSERT_TRUE(c);
    model::FoldPlan plan = model::defaultFoldPlan(model::FoldNode::Opat, 3);
    plan.modules[2].address = 5;
    model::FoldApply apply(c->access(), plan, {0, 1, 2});
    QSignalSpy finished(&apply, &model::FoldApply::finished);
    {
        German german;
        apply.start();
        ASSERT_TRUE(finished.wait(kWaitMs) || finished.count() > 0);
        EXPECT_TRUE(apply.modules()[2]
                        .noteTexts()
                        .join(QLatin1Char(' '))
                        .contains(QStringLiteral("Drehschalter")))
            << apply.modules()[2].noteTexts().join(QLatin1Char(' ')).toStdString();
    }
    const QString english = apply.modules()[2].noteTexts().join(QLatin1Char(' '));
    EXPECT_TRUE(english.contains(QStringLiteral("set its rotary switch to 5")))
        << english.toStdString();
}

TEST(ModelTextsLanguage, ParameterEditRefusalInGerman)
{
    const dev::Dictionary &dma = *dictionaries().find("dma-pn-v51");
    model::ParameterDocument doc;
    doc.createNew({&dma, "51", "3", 3, 1}, dictionaries());
    {
        German german;
        doc.setLanguage(model::textLanguage());
        const auto refused = doc.edit(0, dma.find("d1.11"), 5.0);
        ASSERT_TRUE(refused);
        EXPECT_EQ(*refused, QStringLiteral("d1.11 ist nur lesbar."));
        const auto range = doc.edit(0, dma.find("C1.07"), 1e7);
        ASSERT_TRUE(range);
        EXPECT_TRUE(range->contains(QStringLiteral("über dem Maximum 9,999 V")))
            << range->toStdString();
    }
    doc.setLanguage(model::textLanguage());
    EXPECT_EQ(doc.edit(0, dma.find("d1.11"), 5.0), QStringLiteral("d1.11 is read only."));
}

TEST(ModelTextsLanguage, ModuleIdentityInGerman)
{
    const dev::Dictionary &dma = *dictionaries().find("dma-pn-v51");
    model::ParameterDocument doc;
    {
        German german;
        doc.createNew({&dma, "51", "3", 3, 1}, dictionaries());
        EXPECT_EQ(doc.module(0).identity, QStringLiteral("dma-pn-v51 51, Modus 3"));
    }
    doc.createNew({&dma, "51", "3", 3, 1}, dictionaries());
    EXPECT_EQ(doc.module(0).identity, QStringLiteral("dma-pn-v51 51, mode 3"));
}

TEST(ModelTextsLanguage, LinearisationTextsInGerman)
{
    const auto curves = model::findLCurves(*dictionaries().find("opat"), "", "");
    ASSERT_FALSE(curves.empty());
    const model::LCurve &c = curves.front();
    std::vector<model::LPointValue> values; // linear: x2 = 2.500 V, x3 = 3.750 V, x4 = 5.000 V
    for (const model::LPoint &p : c.points)
        values.push_back({*p.x.row->defaultValue / 1000.0, *p.y.row->defaultValue / 1000.0});
    model::LCoordinate inactive = c.points[1].x;
    inactive.fixedBy = model::LFixedBy::Inactive;

    German german;
    const dev::Language lang = model::textLanguage();
    EXPECT_EQ(model::fixedText(c.points[0].x, lang),
              QStringLiteral("L1.x0 ist vom Gerät fest auf 0,000 V gesetzt"));
    EXPECT_EQ(model::fixedText(inactive, lang),
              QStringLiteral("L1.x1 ist in diesem Gerät nicht aktiv"));
    EXPECT_EQ(model::checkCoordinate(c, values, 3, model::LAxis::X, 2.5, lang),
              QStringLiteral("L1.x3 muss größer als L1.x2 (2,500 V) sein"));
}

} // namespace
} // namespace vt::test
