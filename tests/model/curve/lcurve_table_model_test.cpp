// LCurveTableModel: the L-block points as an editable table that reports each accepted edit once
// and refuses fixed coordinates and crossed x with a reason.
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve_table_model.h"
#include "qt_printers.h"

#include <QAbstractItemModelTester>
#include <QLocale>
#include <QSignalSpy>
#include <cmath>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

const dev::Dictionary &opat()
{
    return *dev::builtinDictionaries()->find("opat");
}

std::optional<double> defaultDisplay(const dev::ParamMeta &row)
{
    return row.defaultValue ? std::optional(*row.defaultValue * 0.001) : std::nullopt;
}

class LCurveTableModelTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        model.setDictionary(opat(), "", "");
        tester = std::make_unique<QAbstractItemModelTester>(
            &model, QAbstractItemModelTester::FailureReportingMode::Fatal);
        model.setValues(defaultDisplay);
        connect();
    }
    void TearDown() override { QLocale::setDefault(QLocale::c()); }

    void connect()
    {
        QObject::connect(&model, &LCurveTableModel::rowsEdited,
                         [this](const QList<LCurveRowEdit> &e) { batches.push_back(e); });
    }

    LCurveTableModel model;
    std::unique_ptr<QAbstractItemModelTester> tester;
    std::vector<QList<LCurveRowEdit>> batches;
};

TEST_F(LCurveTableModelTest, OneRowPerPointTwoColumnsPerCurve)
{
    EXPECT_EQ(model.rowCount(), 9);
    EXPECT_EQ(model.columnCount(), 4);
    EXPECT_EQ(model.headerData(0, Qt::Horizontal).toString(), "L1 x (V)");
    EXPECT_EQ(model.headerData(3, Qt::Horizontal).toString(), "L2 y (V)");
    EXPECT_EQ(model.headerData(8, Qt::Vertical).toString(), "P8");
    const QModelIndex x3 = model.indexOf(0, 3, LAxis::X);
    EXPECT_EQ(x3.data().toString(), "3.750");
    EXPECT_DOUBLE_EQ(x3.data(Qt::EditRole).toDouble(), 3.75);
    const auto *row = reinterpret_cast<const dev::ParamMeta *>(
        x3.data(LCurveTableModel::RowMetaRole).value<quintptr>());
    ASSERT_NE(row, nullptr);
    EXPECT_EQ(row->name, "L1.x3");
    EXPECT_EQ(model.indexOf(1, 2, LAxis::Y).data(LCurveTableModel::RowMetaRole).value<quintptr>(),
              reinterpret_cast<quintptr>(opat().find("L2.y2")));
    EXPECT_DOUBLE_EQ(x3.data(LCurveTableModel::MaxRole).toDouble(), 9.999);
    EXPECT_EQ(x3.data(LCurveTableModel::DecimalsRole).toInt(), 3);
}

TEST_F(LCurveTableModelTest, FixedCoordinatesAreNotEditableAndRefuseEdits)
{
    const QModelIndex x0 = model.indexOf(0, 0, LAxis::X);
    const QModelIndex x8 = model.indexOf(1, 8, LAxis::X);
    EXPECT_FALSE(model.flags(x0) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.flags(x8) & Qt::ItemIsEditable);
    EXPECT_TRUE(model.flags(model.indexOf(0, 0, LAxis::Y)) & Qt::ItemIsEditable);
    EXPECT_TRUE(x0.data(LCurveTableModel::FixedRole).toBool());
    EXPECT_TRUE(x0.data(Qt::ToolTipRole).toString().contains("fixed by the device at 0.000 V"));

    QSignalSpy refused(&model, &LCurveTableModel::editRefused);
    EXPECT_FALSE(model.setData(x0, 0.5));
    ASSERT_EQ(refused.size(), 1);
    EXPECT_EQ(refused[0][2].toString(), "L1.x0 is fixed by the device at 0.000 V");
    EXPECT_DOUBLE_EQ(*model.value(0, 0, LAxis::X), 0.0);
    EXPECT_TRUE(batches.empty());
}

TEST_F(LCurveTableModelTest, AnEditIsStoredAndAnnouncedOnce)
{
    QSignalSpy points(&model, &LCurveTableModel::pointEdited);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    EXPECT_TRUE(model.setData(model.indexOf(0, 3, LAxis::Y), 4.1234));
    ASSERT_EQ(batches.size(), 1u);
    ASSERT_EQ(batches[0].size(), 1);
    EXPECT_EQ(batches[0][0].row, opat().find("L1.y3"));
    EXPECT_DOUBLE_EQ(batches[0][0].display, 4.123); // on the 1 mV raster
    ASSERT_EQ(points.size(), 1);
    EXPECT_EQ(points[0][0].toInt(), 0);
    EXPECT_EQ(points[0][1].toInt(), 3);
    EXPECT_DOUBLE_EQ(points[0][2].toDouble(), 3.75);
    EXPECT_DOUBLE_EQ(points[0][3].toDouble(), 4.123);
    EXPECT_GE(changed.size(), 1);
    EXPECT_EQ(model.indexOf(0, 3, LAxis::Y).data().toString(), "4.123");

    // Both coordinates of a dragged point: one batch of two rows.
    EXPECT_FALSE(model.editPoint(1, 4, 4.5, 2.0));
    ASSERT_EQ(batches.size(), 2u);
    ASSERT_EQ(batches[1].size(), 2);
    EXPECT_EQ(batches[1][0].row->name, "L2.x4");
    EXPECT_EQ(batches[1][1].row->name, "L2.y4");

    // The same value again is no edit.
    EXPECT_FALSE(model.editPoint(1, 4, 4.5, 2.0));
    EXPECT_EQ(batches.size(), 2u);
}

TEST_F(LCurveTableModelTest, CrossedXIsRefusedWithTheNeighbourNamed)
{
    QSignalSpy refused(&model, &LCurveTableModel::editRefused);
    EXPECT_FALSE(model.setData(model.indexOf(0, 3, LAxis::X), 5.0));
    ASSERT_EQ(refused.size(), 1);
    EXPECT_EQ(refused[0][2].toString(), "L1.x3 must be below L1.x4 (5.000 V)");
    EXPECT_DOUBLE_EQ(*model.value(0, 3, LAxis::X), 3.75);
    // A refused x leaves the y of the same edit unapplied too.
    EXPECT_TRUE(model.editPoint(0, 3, 1.0, 1.0).has_value());
    EXPECT_DOUBLE_EQ(*model.value(0, 3, LAxis::Y), 3.75);
    EXPECT_TRUE(batches.empty());
}

TEST_F(LCurveTableModelTest, ValuesFromOutsideRaiseNoEditSignal)
{
    QSignalSpy points(&model, &LCurveTableModel::pointEdited);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    EXPECT_TRUE(model.setRowValue(opat().find("L2.y7"), 1.5));
    EXPECT_FALSE(model.setRowValue(opat().find("C1.02"), 1.0));
    model.setPoint(0, 1, 1.0, std::nullopt);
    EXPECT_DOUBLE_EQ(*model.value(1, 7, LAxis::Y), 1.5);
    EXPECT_DOUBLE_EQ(*model.value(0, 1, LAxis::X), 1.0);
    EXPECT_FALSE(model.value(0, 1, LAxis::Y));
    EXPECT_EQ(model.indexOf(0, 1, LAxis::Y).data().toString(), "");
    EXPECT_EQ(changed.size(), 2);
    EXPECT_EQ(points.size(), 0);
    EXPECT_TRUE(batches.empty());
    // The unknown y is NaN in pointEdited.
    EXPECT_FALSE(model.editPoint(0, 1, 1.1, std::nullopt));
    ASSERT_EQ(points.size(), 1);
    EXPECT_TRUE(std::isnan(points[0][3].toDouble()));
}

TEST_F(LCurveTableModelTest, GermanLocaleShowsCommaAndGermanReasons)
{
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(model.indexOf(0, 1, LAxis::X).data().toString(), "1,250");
    QSignalSpy refused(&model, &LCurveTableModel::editRefused);
    EXPECT_FALSE(model.setData(model.indexOf(0, 2, LAxis::X), 1.0));
    ASSERT_EQ(refused.size(), 1);
    // The numbers follow the locale; the sentence's German words come from the catalogue, which
    // this test does not load (ModelTextsLanguage.LinearisationTextsInGerman has them).
    EXPECT_TRUE(refused[0][2].toString().contains("L1.x2"))
        << refused[0][2].toString().toStdString();
    EXPECT_TRUE(refused[0][2].toString().contains("(1,250 V)"))
        << refused[0][2].toString().toStdString();
}

TEST_F(LCurveTableModelTest, ANewDictionaryResetsTheModel)
{
    QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
    model.setDictionary(*dev::builtinDictionaries()->find("dma-pb-v32"), "", "");
    EXPECT_EQ(reset.size(), 1);
    EXPECT_EQ(model.rowCount(), 0);
    EXPECT_EQ(model.columnCount(), 0);
    EXPECT_TRUE(model.editPoint(0, 0, 1.0, 1.0).has_value());
}

} // namespace
} // namespace vt::model
