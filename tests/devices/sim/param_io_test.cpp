// Parameter access of the plant: IDs by name per family (OPAT "E03" is DMA "E1.03"), cooked
// reads by the row's scale, display writes rounded, clamped and only on change.
#include "plant_test_support.h"

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

TEST(SimParamIo, FindsTheFamilysNameAndSkipsUnimplementedRows)
{
    const ParamRef opat = findParam(family("opat"), {"E1.03", "E03"});
    const ParamRef dma = findParam(family("dma-pn-v51"), {"E1.03", "E03"});
    ASSERT_TRUE(opat.valid());
    ASSERT_TRUE(dma.valid());
    EXPECT_EQ(opat.meta->name, "E03");
    EXPECT_EQ(dma.meta->name, "E1.03");
    EXPECT_FALSE(findParam(family("opat"), "E16").valid()) << "OPAT E16 is 'n' (reserved)";
    EXPECT_FALSE(findParam(family("dma-pb-v15"), "C1.33").valid()) << "removed in V15";
    EXPECT_EQ(branchName("C1.13", 2), "C2.13");
    EXPECT_EQ(branchName("d1.11", 2), "d2.11");
    EXPECT_EQ(branchName("E08", 2), "E08");
}

TEST(SimParamIo, ReadsCookedValuesAndSeconds)
{
    const Dictionary &dict = family("dma-pn-v51");
    ParamMemory mem(dict);
    ParamReader read(mem);
    EXPECT_DOUBLE_EQ(read.value(findParam(dict, "C1.13"), 0), 1.0); // default 100 == 1.00
    mem.set("r1.01", 150);                                          // 1 == 10 ms
    EXPECT_DOUBLE_EQ(read.seconds(findParam(dict, "r1.01"), 0), 1.5);
    mem.set("C1.14", 25); // 100 == 1.00 s
    EXPECT_DOUBLE_EQ(read.seconds(findParam(dict, "C1.14"), 0), 0.25);
    EXPECT_DOUBLE_EQ(read.value(ParamRef{}, 7.0), 7.0);
}

TEST(SimParamIo, PublisherRoundsClampsAndWritesOnlyChanges)
{
    const Dictionary &dict = family("opat");
    ParamMemory mem(dict);
    ParamPublisher out(mem);
    const ParamRef d107 = findParam(dict, "d1.07");
    const std::size_t before = mem.writes();
    out.publish(d107, 1.23449);
    EXPECT_EQ(mem.get("d1.07"), 1234);
    out.publish(d107, 1.2341); // same raw value: no write
    EXPECT_EQ(mem.writes(), before + 1);
    out.publish(d107, 9.0); // above the row's 5.000 A
    EXPECT_EQ(mem.get("d1.07"), 5000);
    out.publish(ParamRef{}, 1.0); // a row the family lacks is never written
    EXPECT_EQ(mem.writes(), before + 2);
}
