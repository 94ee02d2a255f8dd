// Parameter files (docs/FILE-FORMAT.md): a whole module read from the dictionaries
// round-trips exactly, unknown keys and rows survive a save (nothing is dropped on
// save), and display texts are for people only.
#include "file_test_support.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::files;
using vt::dev::files::test::dictionary;
using vt::dev::files::test::moduleFromDefaults;
using vt::dev::files::test::Rows;

namespace {

ParamFile foldFile()
{
    ParamFile f;
    f.tool = "ValveTune 0.1.0";
    f.created = "2024-05-02T09:30:00Z";
    f.note = "Press 1 after commissioning";
    // Every row, process and live values included: the codec keeps whatever a file holds, as
    // older versions saved it.
    f.modules.push_back(moduleFromDefaults("dma-pn-v51", 1, "51.02", "3", Rows::All));
    f.modules.push_back(
        moduleFromDefaults("wandfluh-sd7", 2, "SD7 device type 58352", "vpoc", Rows::All));
    f.modules[0].label = "Axis A, \"main\" cylinder";
    return f;
}

ParamFile parsed(const std::string &text)
{
    auto r = parseParamFile(text);
    if (!r.ok())
        throw std::runtime_error(r.error().text().en);
    return std::move(r).value();
}

} // namespace

TEST(ParamFile, EveryRowOfTwoFamiliesRoundTripsExactly)
{
    const ParamFile f = foldFile();
    ASSERT_EQ(f.modules[0].values.size(), dictionary("dma-pn-v51").params.size());
    ASSERT_EQ(f.modules[1].values.size(), dictionary("wandfluh-sd7").params.size());
    const std::string text = writeParamFile(f);
    const ParamFile back = parsed(text);
    EXPECT_EQ(back, f);
    EXPECT_EQ(writeParamFile(back), text);
}

TEST(ParamFile, DisplayTextsComeFromTheDictionaryAndDoNotChangeValues)
{
    ParamFile f = foldFile();
    for (ValueRow &row : f.modules[0].values)
        if (row.name == "C1.07")
            row.raw = 1000.0;
    const DictionarySet &set = *builtinDictionaries();
    const std::string en = writeParamFile(f, &set, Language::English);
    const std::string de = writeParamFile(f, &set, Language::German);
    EXPECT_NE(en.find(R"({"name": "C1.07", "id": 48, "raw": 1000, "display": "1.000 V"})"),
              std::string::npos)
        << en;
    EXPECT_NE(de.find(R"({"name": "C1.07", "id": 48, "raw": 1000, "display": "1,000 V"})"),
              std::string::npos);
    EXPECT_NE(en.find(R"("display": "off")"), std::string::npos); // enum rows show their label

    ParamFile fromEn = parsed(en), fromDe = parsed(de);
    for (ParamFile *p : {&fromEn, &fromDe})
        for (ModuleRecord &m : p->modules)
            for (ValueRow &row : m.values)
                row.display.clear();
    EXPECT_EQ(fromEn, f);
    EXPECT_EQ(fromDe, f);
    EXPECT_EQ(writeParamFile(parsed(en), &set, Language::English), en);
}

TEST(ParamFile, DisplayIsIgnoredOnRead)
{
    const std::string text = R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": [
        {"address": 1, "family": "dma-pn-v51", "values": [
            {"name": "C1.07", "id": 48, "raw": 1000, "display": "7.5 V"}]}]})";
    const ParamFile f = parsed(text);
    EXPECT_EQ(rawNumber(f.modules[0].values[0].raw), 1000);
    EXPECT_NE(
        writeParamFile(f, builtinDictionaries().operator->()).find("\"display\": \"1.000 V\""),
        std::string::npos);
}

TEST(ParamFile, NumbersKeepTheirExactValueAndKind)
{
    ParamFile f;
    ModuleRecord m;
    m.family = "wandfluh-sd7";
    const double values[] = {0.0,          -0.0,
                             1.0,          -32768.0,
                             4294967295.0, 0.1,
                             1.0 / 3.0,    3.4028234663852886e38,
                             1e-45,        9007199254740992.0,
                             1e300};
    for (std::size_t i = 0; i < std::size(values); ++i)
        m.values.push_back({"n" + std::to_string(i),
                            std::nullopt,
                            {},
                            {},
                            {},
                            values[i],
                            {},
                            nlohmann::json::object()});
    m.values.push_back({"text",
                        std::nullopt,
                        {},
                        {},
                        {},
                        std::string("Ventil \"A\" ÄÖÜ\t\\ 1000"),
                        {},
                        nlohmann::json::object()});
    m.values.push_back({"numeric text",
                        std::nullopt,
                        {},
                        {},
                        {},
                        std::string("1000"),
                        {},
                        nlohmann::json::object()});
    f.modules.push_back(m);
    const std::string text = writeParamFile(f);
    EXPECT_NE(text.find(R"({"name": "n2", "raw": 1})"), std::string::npos)
        << text;                                                               // integer, no ".0"
    EXPECT_NE(text.find(R"({"name": "n1", "raw": -0.0})"), std::string::npos); // sign kept
    EXPECT_NE(text.find(R"({"name": "n5", "raw": 0.1})"), std::string::npos);  // shortest exact
    EXPECT_NE(text.find(R"({"name": "numeric text", "raw": "1000"})"),
              std::string::npos); // a string stays one
    const ParamFile back = parsed(text);
    EXPECT_EQ(back, f);
    EXPECT_TRUE(std::signbit(rawNumber(back.modules[0].values[1].raw)));
    EXPECT_TRUE(isText(back.modules[0].values.back().raw));
}

TEST(ParamFile, NonFiniteFloatsAreWrittenAsTaggedObjects)
{
    // HART float32 values use NaN for "not available" (HART manual); JSON has no NaN.
    ParamFile f;
    ModuleRecord m;
    m.family = "wandfluh-sd7";
    m.values.push_back(
        makeValueRow(*dictionary("wandfluh-sd7").find("hart_PvValue"), std::nan("")));
    m.values.push_back({"inf", std::nullopt, {}, {}, {}, -HUGE_VAL, {}, nlohmann::json::object()});
    f.modules.push_back(m);
    const std::string text = writeParamFile(f, builtinDictionaries().operator->());
    EXPECT_NE(text.find(R"("raw": {"number": "NaN"})"), std::string::npos) << text;
    const ParamFile back = parsed(text);
    EXPECT_TRUE(std::isnan(rawNumber(back.modules[0].values[0].raw)));
    EXPECT_EQ(rawNumber(back.modules[0].values[1].raw), -HUGE_VAL);
    EXPECT_EQ(writeParamFile(back, builtinDictionaries().operator->()), text);
}

TEST(ParamFile, UnknownKeysAndRowsAreWrittenBack)
{
    const std::string text = R"({
      "format": "valvetune-parameters", "formatVersion": 1, "tool": "ValveTune 1.4",
      "created": "2031-01-01T00:00:00Z", "signature": {"by": "QA", "codes": [1, 2.5, null, true]},
      "modules": [{
        "address": 3, "family": "dma-pb-v32", "version": "32.11", "mode": "4", "wiring": "X1:5",
        "values": [
          {"name": "C1.07", "id": 48, "raw": 1500, "checked": true, "history": [1000, 1200]},
          {"name": "Z9.99", "id": 4000, "raw": 7, "display": "from a future version"},
          {"name": "dop_future", "ind": 9, "pnu": 200, "instance": 2, "raw": "text"}
        ]}]})";
    const ParamFile f = parsed(text);
    EXPECT_EQ(f.extra["signature"]["by"], "QA");
    EXPECT_EQ(f.modules[0].extra["wiring"], "X1:5");
    EXPECT_EQ(f.modules[0].values[0].extra["history"][1], 1200);
    ASSERT_EQ(f.modules[0].values.size(), 3u);
    EXPECT_EQ(f.modules[0].values[2].instance, 2);

    for (const DictionarySet *set :
         {static_cast<const DictionarySet *>(nullptr), builtinDictionaries().operator->()}) {
        const std::string out = writeParamFile(f, set);
        EXPECT_NE(out.find(R"("signature": {"by":"QA","codes":[1,2.5,null,true]},)"),
                  std::string::npos)
            << out;
        EXPECT_NE(out.find(R"("wiring": "X1:5",)"), std::string::npos);
        EXPECT_NE(out.find(R"({"name": "C1.07", "id": 48, "raw": 1500)"), std::string::npos);
        EXPECT_NE(out.find(R"("checked": true, "history": [1000,1200]})"), std::string::npos);
        // The unknown row keeps its display: no dictionary row can recompute it.
        EXPECT_NE(
            out.find(
                R"({"name": "Z9.99", "id": 4000, "raw": 7, "display": "from a future version"})"),
            std::string::npos);
        ParamFile again = parsed(out);
        if (set)
            again.modules[0].values[0].display.clear();
        EXPECT_EQ(again, f);
    }
}

TEST(ParamFile, ExtraKeysNeverShadowTheKnownOnes)
{
    ParamFile f;
    f.extra["modules"] = "not this";
    f.extra["formatVersion"] = 99;
    ModuleRecord m;
    m.family = "opat";
    m.extra["values"] = 1;
    ValueRow row{"C1.07", 48, {}, {}, {}, 5.0, {}, nlohmann::json::object()};
    row.extra["raw"] = "no";
    m.values.push_back(row);
    f.modules.push_back(m);
    const ParamFile back = parsed(writeParamFile(f));
    EXPECT_EQ(rawNumber(back.modules[0].values[0].raw), 5);
    EXPECT_TRUE(back.extra.empty());
    EXPECT_TRUE(back.modules[0].values[0].extra.empty());
}

TEST(ParamFile, EmptyFileAndLookups)
{
    ParamFile f;
    f.tool = "t";
    const ParamFile back = parsed(writeParamFile(f));
    EXPECT_EQ(back, f);
    const ParamFile fold = foldFile();
    ASSERT_NE(fold.findModule(2), nullptr);
    EXPECT_EQ(fold.findModule(2)->family, "wandfluh-sd7");
    EXPECT_EQ(fold.findModule(9), nullptr);
    ASSERT_NE(fold.modules[0].find("C1.07"), nullptr);
    EXPECT_EQ(fold.modules[0].find("C1.07")->id, 48);
}

TEST(ParamFile, MakeValueRowCarriesTheAddresses)
{
    const ValueRow hcs = makeValueRow(*dictionary("dma-pn-v51").find("E22"), 1.0);
    EXPECT_EQ(hcs.id, 163);
    EXPECT_FALSE(hcs.ind.has_value());
    const ValueRow hart = makeValueRow(*dictionary("wandfluh-sd7").find("db_DeviceMode"), 1.0);
    EXPECT_EQ(hart.ind, 0);
    EXPECT_EQ(hart.pnu, 39);
    EXPECT_FALSE(hart.instance.has_value()); // instance 0 is the default and not written
}

TEST(ParamFile, IsoUtc)
{
    using namespace std::chrono;
    const sys_days day = year{2024} / May / 2;
    EXPECT_EQ(isoUtc(day + 9h + 30min + 5s + 700ms), "2024-05-02T09:30:05Z");
    EXPECT_EQ(isoUtc(sys_days{year{1999} / December / 31} + 23h + 59min + 59s),
              "1999-12-31T23:59:59Z");
}
