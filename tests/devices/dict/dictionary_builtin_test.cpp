// The embedded dictionaries load, validate, and hold every device family.
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

const DictionarySet &builtin()
{
    const auto &r = builtinDictionaries();
    if (!r.ok()) {
        for (const auto &e : r.error())
            ADD_FAILURE() << e.text();
        static const DictionarySet empty;
        return empty;
    }
    return *r;
}

} // namespace

TEST(Dictionaries, EveryEmbeddedFamilyLoadsAndValidates)
{
    const auto &r = builtinDictionaries();
    ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().front().text());
    EXPECT_EQ(r->families(),
              (std::vector<std::string>{"dma-pb-v15", "dma-pb-v22", "dma-pb-v32", "dma-pn-v13",
                                        "dma-pn-v51", "opat", "wandfluh-ed1", "wandfluh-sd7"}));
}

TEST(Dictionaries, EveryRowHasGermanText)
{
    for (const std::string &family : builtin().families()) {
        for (const ParamMeta &p : builtin().find(family)->params) {
            EXPECT_FALSE(p.label.de.empty()) << family << " " << p.name;
            if (!p.description.en.empty()) {
                EXPECT_FALSE(p.description.de.empty()) << family << " " << p.name;
            }
            for (const EnumLabel &e : p.enums)
                EXPECT_TRUE(e.text.complete()) << family << " " << p.name << " enum " << e.value;
        }
    }
}

// Cooking round-trips for every row at min, max and a middle value in both languages.
TEST(Dictionaries, CookingRoundTripsEveryRowInBothLanguages)
{
    int checked = 0;
    for (const std::string &family : builtin().families()) {
        for (const ParamMeta &p : builtin().find(family)->params) {
            if (p.isString())
                continue;
            const double mid =
                p.isFloat() ? (p.min / 2 + p.max / 2) : std::floor(p.min / 2 + p.max / 2);
            for (double raw : {p.min, p.max, mid}) {
                if (p.isFloat() && std::fabs(raw) > 1e9)
                    continue; // ±FLT_MAX limits of an unbounded float: not a typed value
                for (Language lang : {Language::English, Language::German}) {
                    const std::string shown = formatValue(p, raw, lang);
                    const auto back = parseValue(p, shown, lang);
                    ASSERT_TRUE(back.ok())
                        << family << " " << p.name << " raw " << raw << " shown '" << shown
                        << "': " << back.error().message.en;
                    if (p.isFloat())
                        EXPECT_NEAR(*back, raw, std::fabs(raw) * 1e-6 + 1e-3)
                            << family << " " << p.name;
                    else
                        EXPECT_EQ(*back, raw)
                            << family << " " << p.name << " shown '" << shown << "'";
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 5000);
}

TEST(Dictionaries, HcsRowsMapToTheCanopenManufacturerArea)
{
    const ParamMeta *c107 = builtin().find("opat")->find("C1.07");
    ASSERT_NE(c107, nullptr);
    ASSERT_TRUE(c107->canopen.has_value());
    EXPECT_EQ(c107->canopen->index, 0x2000 + 0x30);
    EXPECT_EQ(c107->canopen->sub, 0);
}
