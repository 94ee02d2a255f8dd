// FieldTreeModel: the tree follows the Description's depths, passes
// QAbstractItemModelTester, and maps a byte back to the deepest field covering it.
#include "hcs/describe.h"
#include "hcs/worked_examples.h"
#include "model/inspect/field_tree_model.h"

#include <QAbstractItemModelTester>
#include <gtest/gtest.h>

using namespace vt::dev;
using vt::model::FieldTreeModel;

namespace {

Description sample()
{
    Description d;
    d.protocol = "test";
    d.fields = {{"A", 0, 2, 0, "0x0102", {"a", "a"}},
                {"A.hi", 0, 1, 1, "1", {"high", "hoch"}},
                {"A.hi.bit0", 0, 1, 2, "1", {"bit", "Bit"}},
                {"A.lo", 1, 1, 1, "2", {"low", "niedrig"}},
                {"B", 2, 1, 0, "3", {"b", "b"}},
                {"note", 0, 0, 0, "", {"explanation", "Erklärung"}},
                {"C.deep", 3, 1, 3, "4", {"slipped depth", "verrutschte Tiefe"}}};
    return d;
}

} // namespace

TEST(FieldTreeModel, BuildsTheTreeFromDepths)
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDescription(sample());
    ASSERT_EQ(model.rowCount(), 3); // A, B, note; C.deep hangs under note (depth jump)
    const QModelIndex a = model.index(0, 0);
    EXPECT_EQ(a.data().toString(), "A");
    ASSERT_EQ(model.rowCount(a), 2);
    const QModelIndex hi = model.index(0, 0, a);
    EXPECT_EQ(model.rowCount(hi), 1);
    EXPECT_EQ(model.parent(hi), a);
    EXPECT_EQ(model.index(0, FieldTreeModel::BytesColumn, a).data().toString(), "0");
    EXPECT_EQ(model.index(0, FieldTreeModel::BytesColumn).data().toString(),
              QString::fromUtf8("0–1"));
    EXPECT_EQ(model.index(1, 0).data().toString(), "B");
    EXPECT_EQ(model.rowCount(model.index(2, 0)), 1);
    model.clear();
    EXPECT_EQ(model.rowCount(), 0);
}

TEST(FieldTreeModel, ByteSelectsTheDeepestField)
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDescription(sample());
    EXPECT_EQ(model.indexForByte(0).data(FieldTreeModel::KeyRole).toString(), "A.hi.bit0");
    EXPECT_EQ(model.indexForByte(1).data(FieldTreeModel::KeyRole).toString(), "A.lo");
    EXPECT_EQ(model.indexForByte(2).data(FieldTreeModel::KeyRole).toString(), "B");
    EXPECT_FALSE(model.indexForByte(9).isValid());
    EXPECT_FALSE(model.indexForByte(-1).isValid());
    EXPECT_EQ(model.indexForKey("B").data(FieldTreeModel::OffsetRole).toInt(), 2);
    EXPECT_EQ(model.indexForKey("A").data(FieldTreeModel::LengthRole).toInt(), 2);
}

TEST(FieldTreeModel, LanguageSwitchesMeanings)
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDescription(sample());
    const QModelIndex lo = model.index(1, FieldTreeModel::MeaningColumn, model.index(0, 0));
    EXPECT_EQ(lo.data().toString(), "low");
    model.setLanguage(Language::German);
    EXPECT_EQ(lo.data().toString(), "niedrig");
}

TEST(FieldTreeModel, RealCmd15DescriptionPassesTheTester)
{
    // OPAT manual §3.4.2 request: nested rows per module.
    hcs::DescribeOptions o;
    o.family = hcs::Family::Opat;
    const Description d = hcs::describe(vt::test::hcs_examples::kOpat342Request, o);
    ASSERT_TRUE(d.ok());
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDescription(d);
    EXPECT_GT(model.rowCount(), 3);
    // Every byte of the telegram belongs to some field.
    for (int b = 0; b < static_cast<int>(vt::test::hcs_examples::kOpat342Request.size()); ++b)
        EXPECT_TRUE(model.indexForByte(b).isValid()) << b;
}
