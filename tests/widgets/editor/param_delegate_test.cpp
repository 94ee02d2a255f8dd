// ParamDelegate: the editor a row gets follows its metadata — no editor for read-only
// rows, the enum labels as a list, bits as a checklist, the range and unit shown on a number
// field — and committing goes through the model, which refuses out-of-range input.
#include "dict/dictionary_loader.h"
#include "model/params/param_roles.h"
#include "model/params/parameter_filter_model.h"
#include "model/params/parameter_tree_model.h"
#include "widgets/editor/param_delegate.h"
#include "widgets/editor/parameter_editor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QSignalSpy>
#include <QSplitter>
#include <QStyleOptionViewItem>
#include <QTest>
#include <QTextBrowser>
#include <QTreeView>
#include <QUndoStack>
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

// A live d-value reads as live (normal text and a marker), not as a disabled row; grey stays for
// what can be neither edited nor watched.
TEST_F(DelegateFixture, LiveValuesAreDrawnAsLiveAndOnlyDeadRowsAreGrey)
{
    EXPECT_TRUE(value("d1.11").data(model::LiveRole).toBool());
    EXPECT_FALSE(value("d1.11").data(Qt::ForegroundRole).isValid());
    EXPECT_FALSE(value("C1.07").data(model::LiveRole).toBool());
    EXPECT_FALSE(value("C1.07").data(Qt::ForegroundRole).isValid());
    EXPECT_FALSE(value("S1.08").data(model::LiveRole).toBool()); // reserved: neither
    EXPECT_TRUE(value("S1.08").data(Qt::ForegroundRole).isValid());

    auto greenPixels = [&](const char *name) {
        QImage image(160, 24, QImage::Format_RGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        QStyleOptionViewItem option;
        option.rect = image.rect();
        option.palette = parent.palette();
        delegate.paint(&painter, option, value(name));
        painter.end();
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                n += c.green() > 120 && c.red() < 120 && c.blue() < 120;
            }
        return n;
    };
    EXPECT_GT(greenPixels("d1.11"), 4);
    EXPECT_EQ(greenPixels("C1.07"), 0);
}

// An undo step names the module: a node has the same parameter on every module.
TEST_F(DelegateFixture, UndoTextNamesTheModule)
{
    const auto refused = doc.edit(0, dma.find("C1.07"), 1250.0);
    ASSERT_FALSE(refused.has_value()) << refused->toStdString();
    EXPECT_EQ(doc.undoStack()->undoText(),
              QStringLiteral("module %1 C1.07 = 1.250 V").arg(doc.module(0).address));
}

// F1 on a parameter shows its help beside the tree, opening the pane the user had closed.
TEST(ParameterEditorWidget, F1ShowsTheHelpOfTheParameter)
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    ui::ParameterEditor editor(doc);
    editor.resize(1200, 600);
    editor.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    doc.createNew({&dma, "51", "3", 1, 1}, *dev::builtinDictionaries());
    auto *splitter = editor.findChild<QSplitter *>(QStringLiteral("editorSplitter"));
    ASSERT_TRUE(splitter);
    splitter->setSizes({1200, 0});
    ASSERT_EQ(editor.helpPane()->width(), 0);
    ASSERT_TRUE(editor.selectParameter(0, dma.find("C1.07")));
    editor.view()->setFocus();
    QTest::keyClick(editor.view(), Qt::Key_F1);
    EXPECT_GT(splitter->sizes().at(1), 0);
    EXPECT_TRUE(editor.helpPane()->toPlainText().contains(QStringLiteral("C1.07")));
}

// The filters and a new document bring rows back as the user left them: open blocks stay open.
TEST(ParameterEditorWidget, FiltersAndANewDocumentKeepTheOpenBlocks)
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    ui::ParameterEditor editor(doc);
    editor.show();
    doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries());
    QTreeView *view = editor.view();
    auto blockOf = [&](const char *name) {
        return editor.filterModel()->mapFromSource(
            editor.treeModel()->indexOf(0, dma.find(name)).parent());
    };
    ASSERT_TRUE(blockOf("E22").isValid());
    view->expand(blockOf("E22"));
    EXPECT_FALSE(view->isExpanded(blockOf("d1.11")));
    // An edit, so that "Changed only" keeps something.
    doc.edit(0, dma.find("C1.07"), 1000.0);

    editor.findChild<QCheckBox *>(QStringLiteral("filterChanged"))->setChecked(true);
    EXPECT_FALSE(blockOf("E22").isValid()); // the filter hides the block
    editor.findChild<QCheckBox *>(QStringLiteral("filterChanged"))->setChecked(false);
    ASSERT_TRUE(blockOf("E22").isValid());
    EXPECT_TRUE(view->isExpanded(blockOf("E22")));
    EXPECT_FALSE(view->isExpanded(blockOf("d1.11")));

    editor.searchBox()->setText(QStringLiteral("C1.07"));
    editor.searchBox()->clear();
    EXPECT_TRUE(view->isExpanded(blockOf("E22")));
    EXPECT_FALSE(view->isExpanded(blockOf("d1.11")));

    // Open / New: the same blocks open again.
    doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries());
    EXPECT_TRUE(view->isExpanded(blockOf("E22")));
    EXPECT_FALSE(view->isExpanded(blockOf("d1.11")));
    // A block the user closes stays closed.
    view->collapse(blockOf("E22"));
    editor.findChild<QCheckBox *>(QStringLiteral("filterInactive"))->toggle();
    EXPECT_FALSE(view->isExpanded(blockOf("E22")));
}

TEST(ParameterEditorWidget, AccessColumnShowsItsWholeHeaderAndValues)
{
    const dev::Dictionary &dma = *dev::builtinDictionaries()->find("dma-pn-v51");
    model::ParameterDocument doc;
    ui::ParameterEditor editor(doc);
    editor.resize(700, 400); // narrower than all columns: the last one is not stretched wider
    editor.show();
    doc.createNew({&dma, "51", "3", 3, 1}, *dev::builtinDictionaries());
    QTreeView *view = editor.view();
    const int column = model::ParameterTreeModel::ColAccess;
    ASSERT_FALSE(view->isColumnHidden(column));
    const QString header = editor.treeModel()->headerData(column, Qt::Horizontal).toString();
    ASSERT_FALSE(header.isEmpty());
    EXPECT_GT(view->columnWidth(column), view->header()->fontMetrics().horizontalAdvance(header))
        << header.toStdString();
    const QModelIndex c107 = editor.treeModel()->indexOf(0, dma.find("C1.07"), column);
    const QString access = c107.data().toString();
    ASSERT_FALSE(access.isEmpty());
    EXPECT_GT(view->columnWidth(column), view->fontMetrics().horizontalAdvance(access))
        << access.toStdString();
}

} // namespace
} // namespace vt::test
