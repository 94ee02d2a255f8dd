// Identification from Vers/E00, DSP-408 capability and HART command 0.
#include "dict/dictionary_loader.h"
#include "dict/identify.h"

#include <gtest/gtest.h>

using namespace vt::dev;

TEST(Identify, HcsVersionAndModePickTheFamily)
{
    const DictionarySet &set = *builtinDictionaries();
    auto opat = identifyHcs(set, 3403, 3, HcsProduct::Opat);
    ASSERT_TRUE(opat.ok());
    EXPECT_EQ(opat->family, "opat");
    EXPECT_EQ(opat->version, "34.03");
    EXPECT_TRUE(opat->exact);

    EXPECT_EQ(identifyHcs(set, 1309, 1, HcsProduct::DmaProfinet)->family, "dma-pn-v13");
    EXPECT_EQ(identifyHcs(set, 5102, 4, HcsProduct::DmaProfinet)->family, "dma-pn-v51");
    EXPECT_EQ(identifyHcs(set, 2201, 2, HcsProduct::DmaProfibus)->family, "dma-pb-v22");
    // V31 is both the OPAT CAN slave and DMA PROFIBUS V31: the product decides.
    EXPECT_EQ(identifyHcs(set, 3105, 3, HcsProduct::Opat)->family, "opat");
    EXPECT_EQ(identifyHcs(set, 3105, 3, HcsProduct::DmaProfibus)->family, "dma-pb-v32");
}

TEST(Identify, UnknownVersionFallsBackVisibly)
{
    const DictionarySet &set = *builtinDictionaries();
    auto r = identifyHcs(set, 5301, 3, HcsProduct::DmaProfinet);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->family, "dma-pn-v51");
    EXPECT_FALSE(r->exact);
    EXPECT_NE(r->warning.en.find("unknown software version V53.01"), std::string::npos);
    EXPECT_NE(r->warning.de.find("nächstliegende"), std::string::npos);
    EXPECT_FALSE(identifyHcs(set, 0, 3, HcsProduct::Opat).ok());
}

TEST(Identify, Wandfluh)
{
    const DictionarySet &set = *builtinDictionaries();
    auto ed1 = identifyDsp408(set, 0x00130000u);
    ASSERT_TRUE(ed1.ok());
    EXPECT_EQ(ed1->family, "wandfluh-ed1");
    EXPECT_TRUE(ed1->exact);
    EXPECT_FALSE(identifyDsp408(set, 0x00110000u)->exact);
    // CANopen device type 408 without a capability object: the ED1, with the manual's value named.
    const auto unreported = identifyDsp408(set, 0);
    ASSERT_TRUE(unreported);
    EXPECT_EQ(unreported->family, "wandfluh-ed1");
    EXPECT_FALSE(unreported->exact);
    EXPECT_NE(unreported->warning.en.find("0x00130000"), std::string::npos);

    auto sd7 = identifyHart(set, 24835, 58352);
    ASSERT_TRUE(sd7.ok());
    EXPECT_EQ(sd7->family, "wandfluh-sd7");
    EXPECT_TRUE(sd7->exact);
    EXPECT_FALSE(identifyHart(set, 24835, 1)->exact);
    EXPECT_FALSE(identifyHart(set, 17, 58352).ok());
}
