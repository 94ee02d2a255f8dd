// The editor's item models: QAbstractItemModelTester on the tree, its filter and the
// compare model; typed input in either language; metadata roles for the delegates.
#include "dict/dictionary_loader.h"
#include "model/params/compare_model.h"
#include "model/params/param_roles.h"
#include "model/params/parameter_filter_model.h"
#include "model/params/parameter_tree_model.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

using model::ParameterTreeModel;

const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}
const dev::Dictionary &dma()
{
    return *dictionaries().find("dma-pn-v51");
}

QModelIndex findName(const QAbstractItemModel &m, const QString &name,
                     const QModelIndex &parent = {})
{
    for (int r = 0; r < m.rowCount(parent); ++r) {
        const QModelIndex i = m.index(r, 0, parent);
        if (i.data().toString() == name)
            return i;
        const QModelIndex below = findName(m, name, i);
        if (below.isValid())
            return below;
    }
    return {};
}

int countParameters(const QAbstractItemModel &m, const QModelIndex &parent = {})
{
    int n = 0;
    for (int r = 0; r < m.rowCount(parent); ++r) {
        const QModelIndex i = m.index(r, 0, parent);
        if (i.data(model::NodeKindRole).toInt() == static_cast<int>(model::NodeKind::Parameter))
            ++n;
        n += countParameters(m, i);
    }
    return n;
}

TEST(ParameterTreeModel, PassesTheModelTesterThroughEditsResetsAndFilters)
{
    model::ParameterDocument doc;
    ParameterTreeModel tree(doc);
    QAbstractItemModelTester treeTester(&tree,
                                        QAbstractItemModelTester::FailureReportingMode::Fatal);
    model::ParameterFilterModel filter;
    filter.setSourceModel(&tree);
    QAbstractItemModelTester filterTester(&filter,
                                          QAbstractItemModelTester::FailureReportingMode::Fatal);

    doc.createNew({&dma(), "51", "3", 3, 2}, dictionaries());
    ASSERT_EQ(tree.rowCount(), 2);
    // module → block (d C E A L r S B system) → branch → parameter
    const QModelIndex c107 = tree.indexOf(0, dma().find("C1.07"));
    ASSERT_TRUE(c107.isValid());
    EXPECT_EQ(c107.parent().data().toString(), "Branch 1");
    EXPECT_EQ(c107.parent().parent().data().toString(), "C");
    EXPECT_EQ(c107.parent().parent().parent(), tree.moduleIndex(0));
    QStringList blocks;
    for (int r = 0; r < tree.rowCount(tree.moduleIndex(0)); ++r)
        blocks << tree.index(r, 0, tree.moduleIndex(0)).data().toString();
    EXPECT_EQ(blocks, (QStringList{"d", "C", "E", "A", "L", "r", "S",
                                   "system"})); // no B (PROFIdrive) on PROFINET

    const QModelIndex value = c107.siblingAtColumn(ParameterTreeModel::ColValue);
    EXPECT_TRUE(tree.flags(value) & Qt::ItemIsEditable);
    EXPECT_TRUE(tree.setData(value, QStringLiteral("1.000")));
    EXPECT_EQ(doc.value(0, dma().find("C1.07")), dev::RawValue{1000.0});
    EXPECT_EQ(value.data().toString(), "1.000 V");

    // Filters: changed only shows the one edited row; search by German label.
    const int all = countParameters(filter);
    filter.setChangedOnly(true);
    EXPECT_EQ(countParameters(filter), 1);
    filter.setChangedOnly(false);
    filter.setSearchText(QStringLiteral("Totbereich"));
    EXPECT_GE(countParameters(filter), 2);
    EXPECT_LT(countParameters(filter), all);
    filter.setSearchText({});
    filter.setShowInactive(true);
    EXPECT_GT(countParameters(filter), all); // reserved (x) rows are hidden unless asked for

    doc.undoStack()->undo();
    doc.clear();
    EXPECT_EQ(tree.rowCount(), 0);
}

TEST(ParameterTreeModel, RolesCarryTheMetadataForTheDelegates)
{
    model::ParameterDocument doc;
    ParameterTreeModel tree(doc);
    doc.createNew({&dma(), "51", "3", 3, 1}, dictionaries());
    const QModelIndex c107 = tree.indexOf(0, dma().find("C1.07"), ParameterTreeModel::ColValue);
    EXPECT_EQ(c107.data(model::UnitRole).toString(), "V");
    EXPECT_DOUBLE_EQ(c107.data(model::DisplayMaxRole).toDouble(), 9.999);
    EXPECT_EQ(c107.data(model::DecimalsRole).toInt(), 3);
    EXPECT_FALSE(c107.data(model::ReadOnlyRole).toBool());
    const QModelIndex d111 = tree.indexOf(0, dma().find("d1.11"), ParameterTreeModel::ColValue);
    EXPECT_TRUE(d111.data(model::ReadOnlyRole).toBool());
    EXPECT_FALSE(tree.flags(d111) & Qt::ItemIsEditable);
    const QModelIndex e00 = tree.indexOf(0, dma().find("E00"), ParameterTreeModel::ColValue);
    EXPECT_FALSE(e00.data(model::EnumLabelsRole).toList().isEmpty());
    EXPECT_FALSE(e00.data(model::HelpRole).toString().isEmpty());
}

TEST(ParameterTreeModel, GermanInputUsesTheDecimalComma)
{
    model::ParameterDocument doc;
    ParameterTreeModel tree(doc);
    doc.createNew({&dma(), "51", "3", 3, 1}, dictionaries());
    doc.setLanguage(dev::Language::German);
    const QModelIndex value = tree.indexOf(0, dma().find("C1.07"), ParameterTreeModel::ColValue);
    EXPECT_TRUE(tree.setData(value, QStringLiteral("1,5")));
    EXPECT_EQ(doc.value(0, dma().find("C1.07")), dev::RawValue{1500.0});
    EXPECT_EQ(value.data().toString(), "1,500 V");
    EXPECT_EQ(tree.headerData(ParameterTreeModel::ColValue, Qt::Horizontal).toString(),
              "Value"); // no catalogue loaded

    QSignalSpy refused(&tree, &ParameterTreeModel::editRefused);
    EXPECT_FALSE(tree.setData(value, QStringLiteral("12")));
    ASSERT_EQ(refused.size(), 1);
    EXPECT_TRUE(refused.at(0).at(1).toString().contains(QStringLiteral("9,999")))
        << refused.at(0).at(1).toString().toStdString();
    EXPECT_EQ(doc.value(0, dma().find("C1.07")), dev::RawValue{1500.0});
}

TEST(CompareModel, ListsDifferencesAndTakesTheChosenOnes)
{
    model::ParameterDocument doc;
    doc.createNew({&dma(), "51", "3", 3, 1}, dictionaries());
    model::CompareModel compare(doc);
    QAbstractItemModelTester tester(&compare,
                                    QAbstractItemModelTester::FailureReportingMode::Fatal);

    dev::files::ParamFile other = doc.toParamFile("test");
    compare.compareWithFile(other, QStringLiteral("same.vtpar"));
    EXPECT_EQ(compare.rowCount(), 0);

    for (auto &v : other.modules[0].values)
        if (v.name == "C1.07" || v.name == "C1.08")
            v.raw = 2000.0;
    compare.compareWithFile(other, QStringLiteral("other.vtpar"));
    ASSERT_EQ(compare.rowCount(), 2);
    EXPECT_TRUE(compare.setData(compare.index(0, model::CompareModel::ColTake), Qt::Checked,
                                Qt::CheckStateRole));
    EXPECT_EQ(compare.applyTaken(), 1);
    EXPECT_EQ(compare.rowCount(), 1);
    doc.undoStack()->undo();
    compare.refresh();
    EXPECT_EQ(compare.rowCount(), 2);
}

} // namespace
} // namespace vt::test
