// The monitor's channel chooser: a module's row names the module and carries its version beside
// the family, so the "Unit" column holds units only.
#include "dict/dictionary_loader.h"
#include "widgets/monitor/channel_chooser.h"

#include <QTreeWidget>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

TEST(ChannelChooser, ModuleRowShowsVersionBesideTheFamilyNotUnderUnit)
{
    const dev::Dictionary *dict = dev::builtinDictionaries()->find("dma-pn-v51");
    ASSERT_TRUE(dict);
    const dev::ParamMeta *desired = dict->find("d1.10");
    ASSERT_TRUE(desired);
    model::ModuleInfo module;
    module.address = 2;
    module.dictionary = dict;
    module.identification.family = "dma-pn-v51";
    module.identification.version = "5.1";
    ui::ChannelSelection offered{{2, {desired}}};
    ui::ChannelChooser chooser({module}, offered, {}, dev::Language::English);

    const QTreeWidgetItem *top = chooser.tree()->topLevelItem(0);
    ASSERT_TRUE(top);
    EXPECT_EQ(top->text(0), QStringLiteral("Module 2"));
    EXPECT_TRUE(top->text(1).contains(QStringLiteral("5.1"))) << top->text(1).toStdString();
    EXPECT_TRUE(top->text(2).isEmpty()) << top->text(2).toStdString(); // the "Unit" column
    ASSERT_EQ(top->childCount(), 1);
    EXPECT_EQ(top->child(0)->text(2), QString::fromStdString(desired->unit));
}

} // namespace
} // namespace vt::test
