// ParamDelegate: the editor a row gets follows its metadata — no editor for read-only
// rows, the enum labels as a list, bits as a checklist, the range and unit shown on a number
// field — and committing goes through the model, which refuses out-of-range input.
#include "dict/dictionary_loader.h"
#include "model/params/param_roles.h"
#include "model/params/parameter_tree_model.h"
#include "widgets/editor/param_delegate.h"
#include "widgets/editor/parameter_editor.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QStyleOptionViewItem>
#include <QTextBrowser>
#include <QTreeView>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

using model::ParameterTreeModel;

struct DelegateFixture : ::testing::Test
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    ParameterTreeModel tree{doc};
    ui::ParamDelegate delegate;
    QWidget parent;

    void SetUp() override { doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries()); }
    QModelIndex value(const char *name)
    {
        return tree.indexOf(0, dma.find(name), ParameterTreeModel::ColValue);
    }
    QWidget *editorFor(const char *name)
    {
        return delegate.createEditor(&parent, QStyleOptionViewItem(), value(name));
    }
};

TEST_F(DelegateFixture, ReadOnlyRowsGetNoEditor)
{
    EXPECT_EQ(editorFor("d1.11"), nullptr);
}

TEST_F(DelegateFixture, NumberFieldShowsRangeAndUnitAndCommitsThroughTheModel)
{
    auto *edit = qobject_cast<QLineEdit *>(editorFor("C1.07"));
    ASSERT_NE(edit, nullptr);
    EXPECT_EQ(edit->placeholderText(), "0.000 … 9.999 V");
    delegate.setEditorData(edit, value("C1.07"));
    edit->setText(QStringLiteral("2.5"));
    delegate.setModelData(edit, &tree, value("C1.07"));
    EXPECT_EQ(doc.value(0, dma.find("C1.07")), dev::RawValue{2500.0});
    edit->setText(QStringLiteral("10.5"));
    delegate.setModelData(edit, &tree, value("C1.07"));
    EXPECT_EQ(doc.value(0, dma.find("C1.07")), dev::RawValue{2500.0}); // refused: above 9.999 V
    EXPECT_TRUE(tree.lastError().contains(QStringLiteral("9.999")));
}

TEST_F(DelegateFixture, EnumRowsOfferTheirLabels)
{
    const dev::ParamMeta *e00 = dma.find("C1.00"); // controller selection: a writable enum
    ASSERT_FALSE(e00->enums.empty());
    auto *combo = qobject_cast<QComboBox *>(editorFor("C1.00"));
    ASSERT_NE(combo, nullptr);
    EXPECT_EQ(combo->count(), static_cast<int>(e00->enums.size()));
    EXPECT_TRUE(combo->itemText(0).contains(QString::fromStdString(e00->enums.front().text.en)));
    const dev::EnumLabel &last = e00->enums.back();
    combo->setCurrentIndex(combo->count() - 1);
    delegate.setModelData(combo, &tree, value("C1.00"));
    EXPECT_EQ(doc.value(0, e00), dev::RawValue{static_cast<double>(last.value)});
}

TEST_F(DelegateFixture, BitFieldsAreAChecklist)
{
    // The first writable bit-field row of any built-in dictionary.
    const dev::Dictionary *dict = nullptr;
    const dev::ParamMeta *bits = nullptr;
    for (const std::string &family : dev::builtinDictionaries()->families()) {
        const dev::Dictionary *d = dev::builtinDictionaries()->find(family);
        for (const dev::ParamMeta &row : d->params)
            if (!bits && row.writable() && !row.bits.empty() && row.enums.empty() &&
                row.access == dev::Access::ReadWrite) {
                dict = d;
                bits = &row;
            }
    }
    if (!bits)
        GTEST_SKIP() << "no writable bit-field row in the built-in dictionaries";
    model::ParameterDocument other;
    ParameterTreeModel otherTree(other);
    const std::string mode = !bits->modes.empty()  ? bits->modes.front()
                             : dict->modes.empty() ? std::string()
                                                   : dict->modes.front();
    other.createNew(
        {dict, dict->versions.empty() ? std::string() : dict->versions.front(), mode, -1, 1},
        *dev::builtinDictionaries());
    const QModelIndex index = otherTree.indexOf(0, bits, ParameterTreeModel::ColValue);
    auto *list =
        qobject_cast<QListWidget *>(delegate.createEditor(&parent, QStyleOptionViewItem(), index));
    ASSERT_NE(list, nullptr) << bits->name;
    EXPECT_EQ(list->count(), static_cast<int>(bits->bits.size()));
    list->item(0)->setCheckState(Qt::Checked);
    delegate.setModelData(list, &otherTree, index);
    const auto raw = static_cast<std::uint32_t>(dev::rawNumber(*other.value(0, bits)));
    EXPECT_TRUE(raw & (1u << bits->bits.front().bit));
}

TEST(ParameterEditorWidget, RefusalIsShownUnderTheTreeAndFiltersHideRows)
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    ui::ParameterEditor editor(doc);
    editor.show();
    doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries());
    ASSERT_TRUE(editor.selectParameter(0, dma.find("C1.07")));
    const QModelIndex source =
        editor.treeModel()->indexOf(0, dma.find("C1.07"), ParameterTreeModel::ColValue);
    EXPECT_FALSE(editor.treeModel()->setData(source, QStringLiteral("99")));
    EXPECT_TRUE(editor.messageLabel()->isVisible());
    EXPECT_TRUE(editor.messageLabel()->text().contains(QStringLiteral("9.999")));
    EXPECT_TRUE(editor.helpPane()->toPlainText().contains(QStringLiteral("C1.07")));
}

} // namespace
} // namespace vt::test
