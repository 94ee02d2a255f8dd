// Linearisation C1.02 (d1.03): OPAT "6 = customized curve (L1.x0 … L1.y8)" is piecewise linear
// through the L points (OPAT manual §7 IDs 0x2B, 0xC6..0xD7); the numbered curves 1..5 are our
// documented approximations y = 10 V · (|x| / 10 V)^p.
#include "plant_test_support.h"
#include "sim/linearisation.h"

#include <cmath>

using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

TEST(PlantLinearisation, OpatCustomizedCurveIsPiecewiseLinearThroughL1)
{
    OpenRig rig("opat");
    rig.set("C1.02", 6);
    rig.set("L1.y1", 2500); // (1.250 V -> 2.500 V); the other points keep the identity defaults
    auto d103 = [&](std::int32_t setValue) {
        rig.set("A1.01", setValue);
        rig.run(0.01);
        return rig.get("d1.03");
    };
    EXPECT_EQ(d103(625), 1250);   // half way to X1
    EXPECT_EQ(d103(1250), 2500);  // on X1
    EXPECT_EQ(d103(1875), 2500);  // X1..X2 is flat now (2.5 -> 2.5)
    EXPECT_EQ(d103(5000), 5000);  // untouched segment
    EXPECT_EQ(d103(-625), -1250); // mirrored for negative set values
}

TEST(PlantLinearisation, LinearAndNumberedCurves)
{
    OpenRig rig("dma-pn-v13");
    rig.set("A1.01", 5000);
    rig.run(0.01);
    EXPECT_EQ(rig.get("d1.03"), 5000) << "C1.02 = 0: linear";
    rig.set("C1.02", 5);
    rig.run(0.01);
    EXPECT_EQ(rig.get("d1.03"), 2500) << "curve 5: p = 2";
    EXPECT_NEAR(Linearisation::numberedCurve(1, 5.0), 10.0 * std::pow(0.5, 1.2), 1e-12);
    EXPECT_DOUBLE_EQ(Linearisation::numberedCurve(3, -10.0), -10.0);
}

TEST(PlantLinearisation, CustomCurveSkipsPointsThatDoNotMoveRight)
{
    CustomCurve c;
    for (std::size_t i = 0; i < c.size(); ++i)
        c[i] = {static_cast<double>(i) * 1.25, static_cast<double>(i) * 1.25};
    c[3].x = 1.0; // out of order: ignored
    EXPECT_DOUBLE_EQ(Linearisation::customCurve(c, 3.75 / 2 + 2.5 / 2), 3.125);
    EXPECT_DOUBLE_EQ(Linearisation::customCurve(c, 12.0), 10.0); // beyond X8: Y8 holds
}
