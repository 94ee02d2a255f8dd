// LCurveEditor: dragging a point on the plot edits the model once per drag, clamped to the row
// range and the neighbours' x, with fixed coordinates kept; a table edit redraws the plot
// (L block of the OPAT Profibus manual's parameter list).
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve_table_model.h"
#include "qt_printers.h"
#include "test_wait.h"
#include "widgets/curve/lcurve_editor.h"
#include "widgets/curve/lcurve_plot.h"

#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <gtest/gtest.h>

namespace vt::ui {
namespace {

using model::LAxis;
using model::LCurveRowEdit;
using model::LCurveTableModel;

const dev::Dictionary &opat()
{
    return *dev::builtinDictionaries()->find("opat");
}

class LCurveEditorTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        model.setDictionary(opat(), "", "");
        // L1 linear (0, 1.25 … 9.999 V); L2 output at 1 V + half the input, so no point hides
        // another.
        model.setValues([](const dev::ParamMeta &row) -> std::optional<double> {
            const double v = *row.defaultValue * 0.001;
            return row.name.rfind("L2.y", 0) == 0 ? 1.0 + v / 2 : v;
        });
        QObject::connect(&model, &LCurveTableModel::rowsEdited,
                         [this](const QList<LCurveRowEdit> &e) { batches.push_back(e); });
        editor.setModel(&model);
        editor.resize(1000, 600);
        editor.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
        editor.plot()->replot(); // lay out the axis rect so coordToPixel is real
    }

    QPoint pixel(double x, double y) const
    {
        const LCurvePlot *p = editor.plot();
        return QPoint(qRound(p->xAxis->coordToPixel(x)), qRound(p->yAxis->coordToPixel(y)));
    }

    // Press on point (x, y), move through `via` to `to`, release there.
    void drag(double x, double y, const std::vector<QPoint> &via, QPoint to)
    {
        LCurvePlot *p = editor.plot();
        QTest::mousePress(p, Qt::LeftButton, {}, pixel(x, y));
        for (const QPoint &v : via)
            QTest::mouseMove(p, v);
        QTest::mouseMove(p, to);
        QTest::mouseRelease(p, Qt::LeftButton, {}, to);
    }

    double graphY(int curve, int point) const
    {
        return editor.plot()->curveGraph(curve)->data()->at(point)->value;
    }
    double graphX(int curve, int point) const
    {
        return editor.plot()->curveGraph(curve)->data()->at(point)->key;
    }

    LCurveTableModel model;
    LCurveEditor editor;
    std::vector<QList<LCurveRowEdit>> batches;
};

TEST_F(LCurveEditorTest, PlotShowsBothCurves)
{
    ASSERT_NE(editor.plot()->curveGraph(0), nullptr);
    ASSERT_NE(editor.plot()->curveGraph(1), nullptr);
    EXPECT_EQ(editor.plot()->curveGraph(0)->data()->size(), 9);
    EXPECT_DOUBLE_EQ(graphX(0, 3), 3.75);
    EXPECT_DOUBLE_EQ(graphY(1, 4), 3.5);
    EXPECT_EQ(editor.table()->model(), &model);
}

TEST_F(LCurveEditorTest, ADragIsOneEditWhenReleased)
{
    LCurvePlot *p = editor.plot();
    QTest::mousePress(p, Qt::LeftButton, {}, pixel(3.75, 3.75));
    EXPECT_TRUE(p->dragging());
    QTest::mouseMove(p, pixel(4.0, 5.0));
    QTest::mouseMove(p, pixel(4.2, 6.0));
    EXPECT_TRUE(batches.empty());         // nothing while moving …
    EXPECT_NEAR(graphX(0, 3), 4.2, 0.02); // … but the plot follows the mouse
    EXPECT_NEAR(graphY(0, 3), 6.0, 0.02);
    QTest::mouseRelease(p, Qt::LeftButton, {}, pixel(4.2, 6.0));
    EXPECT_FALSE(p->dragging());

    ASSERT_EQ(batches.size(), 1u);
    ASSERT_EQ(batches[0].size(), 2);
    EXPECT_EQ(batches[0][0].row, opat().find("L1.x3"));
    EXPECT_EQ(batches[0][1].row, opat().find("L1.y3"));
    EXPECT_NEAR(batches[0][0].display, 4.2, 0.02);
    EXPECT_NEAR(batches[0][1].display, 6.0, 0.02);
    // On the 1 mV raster, and what the model and the table now hold.
    EXPECT_NEAR(batches[0][0].display * 1000, std::round(batches[0][0].display * 1000), 1e-6);
    EXPECT_DOUBLE_EQ(*model.value(0, 3, LAxis::X), batches[0][0].display);
    EXPECT_DOUBLE_EQ(*model.value(0, 3, LAxis::Y), batches[0][1].display);
    EXPECT_DOUBLE_EQ(graphX(0, 3), batches[0][0].display);
}

TEST_F(LCurveEditorTest, DragIsClampedBetweenTheNeighboursAndToTheRange)
{
    // Far right and above the top: x stops one raw step before x4 (5.000 V), y at 9.999 V.
    drag(3.75, 3.75, {pixel(6.0, 8.0)}, pixel(9.5, 11.0));
    ASSERT_EQ(batches.size(), 1u);
    ASSERT_EQ(batches[0].size(), 2);
    EXPECT_DOUBLE_EQ(batches[0][0].display, 4.999);
    EXPECT_DOUBLE_EQ(batches[0][1].display, 9.999);
    // Far left and below the bottom: x stops after x2 (2.500 V), y at 0.
    drag(4.999, 9.999, {}, pixel(-1.0, -1.0));
    ASSERT_EQ(batches.size(), 2u);
    EXPECT_DOUBLE_EQ(batches[1][0].display, 2.501);
    EXPECT_DOUBLE_EQ(batches[1][1].display, 0.0);
    EXPECT_TRUE(editor.message().isEmpty());
}

TEST_F(LCurveEditorTest, AFixedXStaysWhileYFollows)
{
    // OPAT: L1.x0 is fixed at 0.000 V; the point only moves up and down.
    drag(0.0, 0.0, {pixel(2.0, 0.5)}, pixel(2.0, 1.0));
    ASSERT_EQ(batches.size(), 1u);
    ASSERT_EQ(batches[0].size(), 1);
    EXPECT_EQ(batches[0][0].row, opat().find("L1.y0"));
    EXPECT_NEAR(batches[0][0].display, 1.0, 0.02);
    EXPECT_DOUBLE_EQ(*model.value(0, 0, LAxis::X), 0.0);
    EXPECT_DOUBLE_EQ(graphX(0, 0), 0.0);
    // L2.x8 is fixed at 9.999 V.
    drag(9.999, 1.0 + 9.999 / 2, {}, pixel(7.0, 3.0));
    ASSERT_EQ(batches.size(), 2u);
    ASSERT_EQ(batches[1].size(), 1);
    EXPECT_EQ(batches[1][0].row, opat().find("L2.y8"));
    EXPECT_DOUBLE_EQ(*model.value(1, 8, LAxis::X), 9.999);
}

TEST_F(LCurveEditorTest, EscapeCancelsADrag)
{
    LCurvePlot *p = editor.plot();
    QTest::mousePress(p, Qt::LeftButton, {}, pixel(5.0, 5.0));
    QTest::mouseMove(p, pixel(5.5, 7.0));
    QTest::keyClick(p, Qt::Key_Escape);
    EXPECT_FALSE(p->dragging());
    EXPECT_DOUBLE_EQ(graphY(0, 4), 5.0);
    QTest::mouseRelease(p, Qt::LeftButton, {}, pixel(5.5, 7.0));
    EXPECT_TRUE(batches.empty());
}

TEST_F(LCurveEditorTest, PressingBesideAPointDoesNotDrag)
{
    LCurvePlot *p = editor.plot();
    const QPoint beside = pixel(5.0, 5.0) + QPoint(qRound(LCurvePlot::kPickRadiusPx) + 4, 0);
    QTest::mousePress(p, Qt::LeftButton, {}, beside);
    EXPECT_FALSE(p->dragging());
    QTest::mouseRelease(p, Qt::LeftButton, {}, beside);
    EXPECT_TRUE(batches.empty());
}

TEST_F(LCurveEditorTest, AClickOnAPointEditsNothingButSelectsIt)
{
    LCurvePlot *p = editor.plot();
    // A pixel off the point's exact position (as a real click is): no edit, not even by rounding.
    const QPoint at = pixel(6.25, 6.25) + QPoint(1, 1);
    QTest::mousePress(p, Qt::LeftButton, {}, at);
    EXPECT_TRUE(p->dragging());
    QTest::mouseMove(p, at + QPoint(1, 0));
    QTest::mouseRelease(p, Qt::LeftButton, {}, at + QPoint(1, 0));
    EXPECT_TRUE(batches.empty());
    EXPECT_DOUBLE_EQ(graphX(0, 5), 6.25);
    EXPECT_EQ(editor.table()->currentIndex(), model.indexOf(0, 5, LAxis::Y));
}

TEST_F(LCurveEditorTest, ATableEditRedrawsThePlot)
{
    QTableView *table = editor.table();
    const QModelIndex y5 = model.indexOf(1, 5, LAxis::Y);
    table->setCurrentIndex(y5);
    table->edit(y5);
    auto *box = table->viewport()->findChild<QDoubleSpinBox *>();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->decimals(), 3);
    EXPECT_DOUBLE_EQ(box->maximum(), 9.999);
    box->setValue(7.25);
    QTest::keyClick(box, Qt::Key_Enter);
    // The view commits an editor's data from a queued call after the key press.
    ASSERT_TRUE(test::waitUntil([&] { return !batches.empty(); }));
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0][0].row, opat().find("L2.y5"));
    EXPECT_DOUBLE_EQ(graphY(1, 5), 7.25);
}

TEST_F(LCurveEditorTest, ARefusedTableEditIsExplained)
{
    EXPECT_FALSE(model.setData(model.indexOf(0, 3, LAxis::X), 6.0));
    EXPECT_EQ(editor.message(), "L1.x3 must be below L1.x4 (5.000 V)");
    EXPECT_DOUBLE_EQ(graphX(0, 3), 3.75);
    EXPECT_FALSE(editor.table()->model()->flags(model.indexOf(0, 0, LAxis::X)) &
                 Qt::ItemIsEditable);
    // The next accepted edit clears the message.
    EXPECT_TRUE(model.setData(model.indexOf(0, 3, LAxis::X), 4.0));
    EXPECT_TRUE(editor.message().isEmpty());
}

TEST_F(LCurveEditorTest, ValuesFromTheDocumentRedrawWithoutAnEdit)
{
    model.setRowValue(opat().find("L1.y6"), 1.0);
    EXPECT_DOUBLE_EQ(graphY(0, 6), 1.0);
    EXPECT_TRUE(batches.empty());
}

TEST_F(LCurveEditorTest, ALanguageChangeReasksTheModelAndFollowsTheLocale)
{
    QSignalSpy headers(&model, &QAbstractItemModel::headerDataChanged);
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(&editor, &change);
    QCoreApplication::sendEvent(editor.plot(), &change);
    QLocale::setDefault(QLocale::c());
    EXPECT_EQ(headers.size(), 2);
    EXPECT_EQ(editor.plot()->locale().language(), QLocale::German);
}

TEST_F(LCurveEditorTest, LosingTheModelEmptiesThePlot)
{
    auto other = std::make_unique<LCurveTableModel>();
    other->setDictionary(opat(), "", "");
    editor.setModel(other.get());
    other.reset();
    EXPECT_EQ(editor.plot()->curveGraph(0), nullptr);
    EXPECT_EQ(editor.plot()->graphCount(), 0);
}

TEST_F(LCurveEditorTest, ThePanelNamesItsModule)
{
    editor.setModule(3);
    EXPECT_TRUE(editor.moduleText().contains(QStringLiteral("Module 3")))
        << editor.moduleText().toStdString();
    EXPECT_TRUE(editor.moduleText().contains(QString::fromStdString(opat().title.en)))
        << editor.moduleText().toStdString();
    editor.setModule(-1);
    EXPECT_FALSE(editor.moduleText().contains(QStringLiteral("Module 3")));
}

// Where both branches' curves lie on each other, a press grabs the branch chosen in the table
// (or grabbed last), the first one until then — never always branch 2.
TEST_F(LCurveEditorTest, OverlappingPointsGoToTheChosenBranch)
{
    model.setValues([](const dev::ParamMeta &row) -> std::optional<double> {
        return *row.defaultValue * 0.001; // L1 and L2 the same line
    });
    editor.plot()->replot();
    LCurvePlot *p = editor.plot();
    QSignalSpy picked(p, &LCurvePlot::pointPicked);
    QTest::mouseClick(p, Qt::LeftButton, {}, pixel(3.75, 3.75));
    ASSERT_EQ(picked.size(), 1);
    EXPECT_EQ(picked.last().at(0).toInt(), 0);

    // Branch 2 chosen in the table: its point is grabbed.
    const QModelIndex cell = model.indexOf(1, 3, LAxis::Y);
    QTest::mouseClick(editor.table()->viewport(), Qt::LeftButton, {},
                      editor.table()->visualRect(cell).center());
    EXPECT_EQ(p->preferredCurve(), 1);
    QTest::mouseClick(p, Qt::LeftButton, {}, pixel(3.75, 3.75));
    ASSERT_EQ(picked.size(), 2);
    EXPECT_EQ(picked.last().at(0).toInt(), 1);
    EXPECT_TRUE(batches.empty()); // clicks edit nothing
}

} // namespace
} // namespace vt::ui
