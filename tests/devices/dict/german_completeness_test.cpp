// Every built-in dictionary, after `extends`, `kind`
// and `remove` are applied, carries German for its title, every label, every description that
// has English, and every enum and bit label. An overlay that overrides a text with English only
// (the whole object replaces the inherited one) is caught here, not in the UI.
#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace vt::dev;

namespace {

// One line per text that lacks German: "dma-pb-v15 0xB0 description".
std::vector<std::string> missingGerman(const Dictionary &dict)
{
    std::vector<std::string> missing;
    const auto check = [&](const LocalText &text, const std::string &where, bool required) {
        if ((required || !text.en.empty()) && text.de.empty())
            missing.push_back(dict.family + " " + where);
    };
    check(dict.title, "title", true);
    for (const ParamMeta &p : dict.params) {
        check(p.label, p.name + " label", true);
        check(p.description, p.name + " description", false);
        for (const EnumLabel &e : p.enums)
            check(e.text, p.name + " enum " + std::to_string(e.value), true);
        for (const BitLabel &b : p.bits)
            check(b.text, p.name + " bit " + std::to_string(b.bit), true);
    }
    return missing;
}

std::vector<std::string> missingGerman(const DictionarySet &set)
{
    std::vector<std::string> missing;
    for (const std::string &family : set.families()) {
        const std::vector<std::string> m = missingGerman(*set.find(family));
        missing.insert(missing.end(), m.begin(), m.end());
    }
    return missing;
}

std::string joined(const std::vector<std::string> &lines)
{
    std::string out;
    for (const std::string &l : lines)
        out += l + "\n";
    return out;
}

// A base with full German and an overlay that overrides texts in English only.
std::vector<DictionaryFile> overlayLackingGerman()
{
    const std::string base = R"({
      "schema": 1, "family": "t-base", "abstract": true,
      "title": {"en": "Test base", "de": "Testbasis"},
      "vendor": "HCS", "protocol": "hcs",
      "parameters": [
        {"name": "C1.01", "id": 16, "block": "C", "access": "rw", "type": "int16", "min": 0, "max": 2,
         "label": {"en": "Gain", "de": "Verstärkung"},
         "description": {"en": "Proportional gain", "de": "Proportionalverstärkung"},
         "enum": [{"value": 0, "en": "off", "de": "aus"}, {"value": 1, "en": "on", "de": "ein"}]},
        {"name": "0xB0", "id": 176, "block": "system", "access": "r", "type": "uint16",
         "label": {"en": "Switches", "de": "Schalter"},
         "bits": [{"bit": 0, "en": "Enable", "de": "Freigabe"}]}
      ]})";
    const std::string overlay = R"({
      "schema": 1, "family": "t-child", "extends": "t-base",
      "title": {"en": "Test child"},
      "parameters": [
        {"name": "C1.01", "description": {"en": "Gain, overridden in English only"},
         "enum": [{"value": 0, "en": "off", "de": "aus"}, {"value": 1, "en": "on"}]},
        {"name": "0xB0", "label": {"en": "Switches", "de": ""},
         "bits": [{"bit": 0, "en": "Enable"}]}
      ]})";
    return {{"t-base.json", base}, {"t-child.json", overlay}};
}

} // namespace

TEST(GermanDictionaries, EveryBuiltinTextHasGermanAfterOverlays)
{
    const auto &r = builtinDictionaries();
    ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().front().text());
    ASSERT_EQ(r->families().size(), 8u);
    const std::vector<std::string> missing = missingGerman(*r);
    EXPECT_TRUE(missing.empty()) << missing.size() << " texts lack German:\n" << joined(missing);
}

// The loader refuses a dictionary whose overlay left texts in English only, naming each text,
// so a built-in dictionary lacking German stops the program at start-up and fails the test above.
TEST(GermanDictionaries, LoaderRefusesAnOverlayThatLeftTextsInEnglish)
{
    const auto r = loadDictionaries(overlayLackingGerman());
    ASSERT_FALSE(r.ok());
    std::vector<std::string> errors;
    for (const DictionaryError &e : r.error())
        errors.push_back(e.text());
    EXPECT_EQ(errors,
              (std::vector<std::string>{"t-child.json: \"title\" needs en and de",
                                        "t-child.json, row C1.01: description has no German text",
                                        "t-child.json, row C1.01: enum 1 has no German text",
                                        "t-child.json, row 0xB0: label has no German text",
                                        "t-child.json, row 0xB0: bit 0 has no German text"}));
}

// The test's own check, independent of the loader's validation, finds the same gaps in a
// dictionary built in memory.
TEST(GermanDictionaries, CheckFindsEveryTextWithoutGerman)
{
    Dictionary dict;
    dict.family = "t-mem";
    dict.title = {"Test", ""};
    ParamMeta gain;
    gain.name = "C1.01";
    gain.label = {"Gain", "Verstärkung"};
    gain.description = {"Proportional gain", ""};
    gain.enums = {{0, {"off", "aus"}}, {1, {"on", ""}}};
    ParamMeta switches;
    switches.name = "0xB0";
    switches.label = {"Switches", ""};
    switches.bits = {{0, {"Enable", ""}}, {1, {"Error", "Fehler"}}};
    ParamMeta quiet; // no description in either language: nothing to translate
    quiet.name = "d1.07";
    quiet.label = {"Current A", "Strom A"};
    dict.params = {gain, switches, quiet};
    EXPECT_EQ(
        missingGerman(dict),
        (std::vector<std::string>{"t-mem title", "t-mem C1.01 description", "t-mem C1.01 enum 1",
                                  "t-mem 0xB0 label", "t-mem 0xB0 bit 0"}));
    dict.title.de = "Test";
    dict.params[0].description.de = "Proportionalverstärkung";
    dict.params[0].enums[1].text.de = "ein";
    dict.params[1].label.de = "Schalter";
    dict.params[1].bits[0].text.de = "Freigabe";
    EXPECT_TRUE(missingGerman(dict).empty()) << joined(missingGerman(dict));
}

TEST(GermanDictionaries, FullyGermanBaseLoads)
{
    std::vector<DictionaryFile> files = overlayLackingGerman();
    files.front().text.replace(files.front().text.find("\"abstract\": true"), 16,
                               "\"abstract\": false");
    files.pop_back();
    const auto r = loadDictionaries(files);
    ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().front().text());
    ASSERT_EQ(r->families(), std::vector<std::string>{"t-base"});
    EXPECT_TRUE(missingGerman(*r).empty()) << joined(missingGerman(*r));
}

// The manuals' German vocabulary (docs/GLOSSARY-DE.md) is used for the recurring terms: a
// label that still says "Set value" or "Actual value" in German was left untranslated.
TEST(GermanDictionaries, GermanLabelsUseNoEnglishControlTerms)
{
    const auto &r = builtinDictionaries();
    ASSERT_TRUE(r.ok());
    const std::vector<std::string> english{
        "Set value", "set value", "Actual value", "actual value", "Gain",
        "Ramp up",   "Ramp down", "Enable",       "Error ",       "Wire break",
        "Solenoid",  "Deadband",  "Dead band"};
    std::vector<std::string> found;
    for (const std::string &family : r->families()) {
        for (const ParamMeta &p : r->find(family)->params) {
            for (const std::string &word : english)
                if (p.label.de.find(word) != std::string::npos)
                    found.push_back(family + " " + p.name + ": " + p.label.de);
        }
    }
    EXPECT_TRUE(found.empty()) << joined(found);
}
