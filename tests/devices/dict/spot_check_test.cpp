// Spot checks of the dictionaries against the manuals (row counts per family
// and at least 40 spot checks). The expected values in tests/devices/data/spot_*.json were copied
// from the manuals by hand, row by row, with the section cited in each check's "source".
#include "dict/dictionary_loader.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace vt::dev;
using Json = nlohmann::json;

namespace {

std::vector<std::filesystem::path> spotFiles()
{
    std::vector<std::filesystem::path> out;
    for (const auto &e : std::filesystem::directory_iterator(VT_SOURCE_DIR "/tests/devices/data"))
        if (e.path().filename().string().rfind("spot_", 0) == 0 && e.path().extension() == ".json")
            out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string where(const Json &check)
{
    return check.value("family", "?") + " " + check.value("name", "?") + " (" +
           check.value("source", "") + ")";
}

void expectField(const ParamMeta &p, const std::string &key, const Json &want,
                 const std::string &ctx)
{
    auto optional = [&](const std::optional<int> &v) {
        ASSERT_TRUE(v.has_value()) << ctx << ": no " << key;
        EXPECT_EQ(*v, want.get<int>()) << ctx << ": " << key;
    };
    if (key == "id")
        optional(p.id);
    else if (key == "ind")
        optional(p.ind);
    else if (key == "pnu")
        optional(p.pnu);
    else if (key == "pzd")
        optional(p.pzd);
    else if (key == "instance")
        EXPECT_EQ(p.instance, want.get<int>()) << ctx;
    else if (key == "block")
        EXPECT_EQ(p.block, want.get<std::string>()) << ctx;
    else if (key == "branch")
        EXPECT_EQ(p.branch, want.get<int>()) << ctx;
    else if (key == "access")
        EXPECT_EQ(accessKey(p.access), want.get<std::string>()) << ctx;
    else if (key == "type")
        EXPECT_EQ(rawTypeKey(p.type), want.get<std::string>()) << ctx;
    else if (key == "min")
        EXPECT_DOUBLE_EQ(p.min, want.get<double>()) << ctx;
    else if (key == "max")
        EXPECT_DOUBLE_EQ(p.max, want.get<double>()) << ctx;
    else if (key == "step")
        EXPECT_DOUBLE_EQ(p.step, want.get<double>()) << ctx;
    else if (key == "default") {
        ASSERT_TRUE(p.defaultValue.has_value()) << ctx << ": no default";
        EXPECT_DOUBLE_EQ(*p.defaultValue, want.get<double>()) << ctx;
    } else if (key == "unit")
        EXPECT_EQ(p.unit, want.get<std::string>()) << ctx;
    else if (key == "scale_factor")
        EXPECT_DOUBLE_EQ(p.scale.name.empty() ? 1.0 : p.scale.factor, want.get<double>()) << ctx;
    else if (key == "label_en")
        EXPECT_EQ(p.label.en, want.get<std::string>()) << ctx;
    else if (key == "label_de")
        EXPECT_EQ(p.label.de, want.get<std::string>()) << ctx;
    else if (key == "enum" || key == "enum_de") {
        for (const auto &[value, text] : want.items()) {
            const EnumLabel *e = p.findEnum(std::stoll(value));
            ASSERT_NE(e, nullptr) << ctx << ": no enum value " << value;
            EXPECT_EQ(key == "enum" ? e->text.en : e->text.de, text.get<std::string>())
                << ctx << " enum " << value;
        }
    } else if (key == "bit") {
        for (const auto &item : want.items()) {
            const int bit = std::stoi(item.key());
            const auto it = std::find_if(p.bits.begin(), p.bits.end(),
                                         [bit](const BitLabel &b) { return b.bit == bit; });
            ASSERT_NE(it, p.bits.end()) << ctx << ": no bit " << bit;
            EXPECT_EQ(it->text.en, item.value().get<std::string>()) << ctx << " bit " << bit;
        }
    } else {
        ADD_FAILURE() << ctx << ": unknown expectation key '" << key << "'";
    }
}

} // namespace

TEST(DictionarySpotChecks, RowCountsAndManualValues)
{
    const auto &set = builtinDictionaries();
    ASSERT_TRUE(set.ok());
    int checks = 0, counted = 0;
    for (const auto &path : spotFiles()) {
        std::ifstream in(path);
        const Json doc = Json::parse(in);
        for (const auto &[family, rows] : doc.at("rows").items()) {
            const Dictionary *d = set->find(family);
            ASSERT_NE(d, nullptr) << path << ": no family " << family;
            EXPECT_EQ(d->params.size(), rows.get<std::size_t>()) << family << " row count";
            ++counted;
        }
        for (const Json &check : doc.at("checks")) {
            const Dictionary *d = set->find(check.at("family").get<std::string>());
            ASSERT_NE(d, nullptr) << where(check);
            const ParamMeta *p = d->find(check.at("name").get<std::string>());
            if (check.value("absent", false)) {
                EXPECT_EQ(p, nullptr) << where(check) << " must not exist";
            } else {
                ASSERT_NE(p, nullptr) << where(check);
                for (const auto &[key, want] : check.at("expect").items())
                    expectField(*p, key, want, where(check));
            }
            ++checks;
        }
    }
    EXPECT_EQ(counted, 8); // every concrete family has its row count checked
    EXPECT_GE(checks, 40);
}
