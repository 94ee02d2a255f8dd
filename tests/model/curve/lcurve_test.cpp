// The L-block curves found in the HCS dictionaries and the checks of an edited point
// (DMA Profinet manual §6 and OPAT Profibus manual, list of parameters, L1.x0 .. L2.y8).
#include "dict/dictionary_loader.h"
#include "model/curve/lcurve.h"

#include <cmath>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

const dev::Dictionary &dictionary(const std::string &family)
{
    const dev::Dictionary *d = dev::builtinDictionaries()->find(family);
    EXPECT_NE(d, nullptr) << family;
    return *d;
}

// A linear curve 0, 1.25, 2.5 … 9.999 V as the dictionaries' defaults.
std::vector<LPointValue> linear(const LCurve &curve)
{
    std::vector<LPointValue> v;
    for (const LPoint &p : curve.points)
        v.push_back({*p.x.row->defaultValue / 1000.0, *p.y.row->defaultValue / 1000.0});
    return v;
}

dev::ParamMeta voltRow(const std::string &name, dev::Access access, double min = 0,
                       double max = 9999)
{
    dev::ParamMeta m;
    m.name = name;
    m.block = "L";
    m.access = access;
    m.min = min;
    m.max = max;
    m.unit = "V";
    m.scale = {"milli", 0.001, 3, dev::Rounding::Nearest, false, ""};
    return m;
}

TEST(LCurve, OpatHasTwoCurvesOfNinePointsWithBothXEndsFixed)
{
    const auto curves = findLCurves(dictionary("opat"), "", "");
    ASSERT_EQ(curves.size(), 2u);
    for (const LCurve &c : curves) {
        SCOPED_TRACE(c.name);
        ASSERT_EQ(c.points.size(), 9u);
        EXPECT_EQ(c.unit, "V");
        EXPECT_EQ(c.points[0].x.row->name, c.name + ".x0");
        EXPECT_EQ(c.points[8].y.row->name, c.name + ".y8");
        ASSERT_NE(c.selector, nullptr);
        EXPECT_EQ(c.selector->name, "C" + std::to_string(c.branch) + ".02");
        // OPAT manual: x0 "(fix)" 0..0 and x8 "(fix)" 9999..9999.
        ASSERT_TRUE(c.points[0].x.fixed());
        EXPECT_EQ(fixedText(c.points[0].x, dev::Language::English).toStdString(),
                  c.name + ".x0 is fixed by the device at 0.000 V");
        // German: ModelTextsLanguage.LinearisationTextsInGerman
        ASSERT_TRUE(c.points[8].x.fixed());
        EXPECT_EQ(fixedText(c.points[8].x, dev::Language::English).toStdString(),
                  c.name + ".x8 is fixed by the device at 9.999 V");
        for (std::size_t i = 1; i < 8; ++i)
            EXPECT_FALSE(c.points[i].x.fixed()) << i;
        for (const LPoint &p : c.points) {
            EXPECT_FALSE(p.y.fixed()) << p.y.row->name;
            EXPECT_DOUBLE_EQ(p.y.min, 0.0);
            EXPECT_DOUBLE_EQ(p.y.max, 9.999);
            EXPECT_DOUBLE_EQ(p.y.step, 0.001);
            EXPECT_EQ(p.y.decimals, 3);
        }
    }
}

TEST(LCurve, DmaProfinetFixesOnlyX0)
{
    // DMA Profinet manual §6: L1.x0 / L2.x0 "(fixed value)"; x8 has the full range 0..9999.
    const auto curves = findLCurves(dictionary("dma-pn-v51"), "51", "3");
    ASSERT_EQ(curves.size(), 2u);
    for (const LCurve &c : curves) {
        ASSERT_EQ(c.points.size(), 9u);
        EXPECT_TRUE(c.points[0].x.fixed());
        EXPECT_FALSE(c.points[8].x.fixed());
        EXPECT_DOUBLE_EQ(c.points[8].x.max, 9.999);
    }
}

TEST(LCurve, DmaProfibusHasNoCurve)
{
    EXPECT_TRUE(findLCurves(dictionary("dma-pb-v32"), "", "").empty());
}

TEST(LCurve, ReadOnlyAndInactiveRowsAreFixedWithTheirReason)
{
    dev::Dictionary d;
    d.params = {voltRow("L1.x0", dev::Access::ReadWrite, 0, 0), voltRow("L1.y0", dev::Access::Read),
                voltRow("L1.x1", dev::Access::Inactive), voltRow("L1.y1", dev::Access::ReadWrite),
                voltRow("L1.x2", dev::Access::ReadWrite)}; // no L1.y2: the curve ends at point 1
    d.buildIndex();
    const auto curves = findLCurves(d, "", "");
    ASSERT_EQ(curves.size(), 1u);
    ASSERT_EQ(curves[0].points.size(), 2u);
    EXPECT_EQ(curves[0].selector, nullptr);
    ASSERT_TRUE(curves[0].points[0].y.fixed());
    EXPECT_EQ(fixedText(curves[0].points[0].y, dev::Language::English), "L1.y0 is read-only");
    ASSERT_TRUE(curves[0].points[1].x.fixed());
    EXPECT_EQ(curves[0].points[1].x.fixedBy, LFixedBy::Inactive);
    EXPECT_EQ(fixedText(curves[0].points[1].x, dev::Language::English),
              "L1.x1 is not active on this device"); // German: ModelTextsLanguage
    EXPECT_FALSE(curves[0].points[1].y.fixed());
}

TEST(LCurve, XMustRiseFromPointToPoint)
{
    const auto curves = findLCurves(dictionary("opat"), "", "");
    const LCurve &c = curves.at(0);
    const auto values = linear(c); // x2 = 2.500 V, x3 = 3.750 V, x4 = 5.000 V
    const LRange r = allowedRange(c, values, 3, LAxis::X);
    EXPECT_DOUBLE_EQ(r.min, 2.501);
    EXPECT_DOUBLE_EQ(r.max, 4.999);

    EXPECT_FALSE(checkCoordinate(c, values, 3, LAxis::X, 2.501));
    EXPECT_FALSE(checkCoordinate(c, values, 3, LAxis::X, 4.999));
    const auto below = checkCoordinate(c, values, 3, LAxis::X, 2.5);
    ASSERT_TRUE(below);
    EXPECT_EQ(*below, "L1.x3 must be above L1.x2 (2.500 V)");
    // German: ModelTextsLanguage.LinearisationTextsInGerman
    const auto above = checkCoordinate(c, values, 3, LAxis::X, 6.0);
    ASSERT_TRUE(above);
    EXPECT_EQ(*above, "L1.x3 must be below L1.x4 (5.000 V)");
}

TEST(LCurve, YIsCheckedAgainstItsRowRangeOnly)
{
    const auto curves = findLCurves(dictionary("opat"), "", "");
    const LCurve &c = curves.at(1);
    const auto values = linear(c);
    // No order for y: a curve may fall (e.g. to compensate a valve's overlap).
    EXPECT_FALSE(checkCoordinate(c, values, 5, LAxis::Y, 0.5));
    const auto high = checkCoordinate(c, values, 5, LAxis::Y, 10.5);
    ASSERT_TRUE(high);
    EXPECT_TRUE(high->contains("L2.y5")) << high->toStdString();
    EXPECT_TRUE(high->contains("9.999 V")) << high->toStdString();
    const LRange r = allowedRange(c, values, 5, LAxis::Y);
    EXPECT_DOUBLE_EQ(r.min, 0.0);
    EXPECT_DOUBLE_EQ(r.max, 9.999);
    EXPECT_TRUE(checkCoordinate(c, values, 5, LAxis::Y, std::nan("")));
}

TEST(LCurve, FixedCoordinateRefusesAnyOtherValue)
{
    const auto curves = findLCurves(dictionary("opat"), "", "");
    const LCurve &c = curves.at(0);
    const auto values = linear(c);
    EXPECT_FALSE(checkCoordinate(c, values, 0, LAxis::X, 0.0)); // its own value: no change
    const auto moved = checkCoordinate(c, values, 0, LAxis::X, 0.5);
    ASSERT_TRUE(moved);
    EXPECT_EQ(*moved, "L1.x0 is fixed by the device at 0.000 V");
    EXPECT_TRUE(checkCoordinate(c, values, 8, LAxis::X, 9.0));
}

TEST(LCurve, UnknownNeighboursLeaveTheRowRange)
{
    const auto curves = findLCurves(dictionary("dma-pn-v51"), "", "");
    const LCurve &c = curves.at(0);
    std::vector<LPointValue> values(c.points.size()); // nothing read yet
    const LRange r = allowedRange(c, values, 4, LAxis::X);
    EXPECT_DOUBLE_EQ(r.min, 0.0);
    EXPECT_DOUBLE_EQ(r.max, 9.999);
    EXPECT_FALSE(checkCoordinate(c, values, 4, LAxis::X, 0.0));
}

TEST(LCurve, NeighboursInWrongOrderLeaveNoRoom)
{
    const auto curves = findLCurves(dictionary("dma-pn-v51"), "", "");
    const LCurve &c = curves.at(0);
    auto values = linear(c);
    values[2].x = 5.0; // as read from a device with a crossed curve (x4 = 5.000 V)
    EXPECT_TRUE(allowedRange(c, values, 3, LAxis::X).empty());
    EXPECT_TRUE(checkCoordinate(c, values, 3, LAxis::X, 3.75));
}

TEST(LCurve, SnapsToTheRawRaster)
{
    const auto curves = findLCurves(dictionary("opat"), "", "");
    const LCoordinate &x = curves.at(0).points.at(3).x;
    EXPECT_DOUBLE_EQ(snapToStep(x, 1.2344), 1.234);
    EXPECT_DOUBLE_EQ(snapToStep(x, 1.2346), 1.235);
    EXPECT_DOUBLE_EQ(snapToStep(x, 0.3), 0.3);
}

} // namespace
} // namespace vt::model
