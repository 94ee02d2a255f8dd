// Export CSV: English with ',' and '.', German with ';' and ',' (what spreadsheets
// expect in each locale), stated in the header comment; fields quoted per RFC 4180.
#include "file_test_support.h"
#include "files/param_csv.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace vt::dev;
using namespace vt::dev::files;
using vt::dev::files::test::dictionary;

namespace {

ModuleRecord sample()
{
    const Dictionary &d = dictionary("dma-pn-v51");
    ModuleRecord m;
    m.address = 1;
    m.family = "dma-pn-v51";
    m.version = "51.02";
    m.mode = "3";
    m.label = "Press 1, axis \"A\"; left";
    m.values.push_back(makeValueRow(*d.find("C1.07"), 1000.0));
    m.values.push_back(makeValueRow(*d.find("C1.00"), 2.0));
    m.values.push_back(
        makeValueRow(*d.find("C1.07"), -1.0)); // (the same meta twice is fine for CSV)
    m.values.back().name = "C1.07 copy";
    m.values.push_back(
        {"X9.99", std::nullopt, {}, {}, {}, 2.5, "2.5 bar, \"est.\"", nlohmann::json::object()});
    return m;
}

std::vector<std::string> lines(const std::string &csv)
{
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t end; (end = csv.find("\r\n", start)) != std::string::npos; start = end + 2)
        out.push_back(csv.substr(start, end - start));
    EXPECT_EQ(start, csv.size()) << "every line ends in CRLF";
    return out;
}

} // namespace

TEST(ParamCsv, EnglishUsesCommaAndPoint)
{
    const auto l = lines(exportCsv(sample(), &dictionary("dma-pn-v51"), {Language::English}));
    ASSERT_EQ(l.size(), 7u);
    EXPECT_EQ(
        l[0],
        "# ValveTune parameter export. Separator: comma. Decimal sign: point. Encoding: UTF-8.");
    EXPECT_EQ(l[1],
              "# Module 1: dma-pn-v51. Version 51.02. Mode 3. Label: Press 1; axis  A ; left");
    EXPECT_EQ(l[2], "Name,Label,Value,Unit,Raw,Range,Access");
    EXPECT_EQ(l[3], "C1.07,Dead band compensation A,1.000,V,1000,0.000 … 9.999,read/write");
    EXPECT_EQ(l[4].substr(0, 17), "C1.00,Controller ");
    EXPECT_NE(l[4].find(",Remote,,2,0 … 4,read/write"), std::string::npos) << l[4];
    EXPECT_EQ(l[5], "C1.07 copy,Dead band compensation A,-0.001,V,-1,0.000 … 9.999,read/write");
    EXPECT_EQ(l[6], "X9.99,,\"2.5 bar, \"\"est.\"\"\",,2.5,,"); // the file's display, quoted
}

TEST(ParamCsv, GermanUsesSemicolonAndComma)
{
    const auto l = lines(exportCsv(sample(), &dictionary("dma-pn-v51"), {Language::German}));
    ASSERT_EQ(l.size(), 7u);
    EXPECT_EQ(l[0], "# ValveTune-Parameterexport. Trennzeichen: Semikolon. Dezimalzeichen: Komma. "
                    "Kodierung: UTF-8.");
    EXPECT_EQ(
        l[1],
        "# Modul 1: dma-pn-v51. Version 51.02. Modus 3. Bezeichnung: Press 1, axis  A , left");
    EXPECT_EQ(l[2], "Name;Bezeichnung;Wert;Einheit;Rohwert;Bereich;Zugriff");
    EXPECT_EQ(l[3], "C1.07;Totbereichkompensation A;1,000;V;1000;0,000 … 9,999;lesen/schreiben");
    EXPECT_NE(l[4].find(";schaltender Regler;;2;0 … 4;lesen/schreiben"), std::string::npos) << l[4];
    EXPECT_EQ(l[6], "X9.99;;\"2.5 bar, \"\"est.\"\"\";;2,5;;");
}

TEST(ParamCsv, FieldsAreQuotedAndFormulasDefused)
{
    EXPECT_EQ(csvField("plain", ','), "plain");
    EXPECT_EQ(csvField("a,b", ','), "\"a,b\"");
    EXPECT_EQ(csvField("a,b", ';'), "a,b");
    EXPECT_EQ(csvField("a;b", ';'), "\"a;b\"");
    EXPECT_EQ(csvField("say \"hi\"", ';'), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csvField("two\nlines", ','), "\"two\nlines\"");
    EXPECT_EQ(csvField(" padded", ','), "\" padded\"");
    EXPECT_EQ(csvField("#not a comment", ','), "\"#not a comment\"");
    EXPECT_EQ(csvField("=HYPERLINK(\"x\")", ','), "\"'=HYPERLINK(\"\"x\"\")\"");
    EXPECT_EQ(csvField("@SUM(A1)", ','), "'@SUM(A1)");
    EXPECT_EQ(csvField("-1,000", ';'), "-1,000"); // a negative number stays a number
    EXPECT_EQ(csvField("-Infinity", ','), "'-Infinity");
    EXPECT_EQ(csvField("", ','), "");
    EXPECT_EQ(csvSeparator(Language::German), ';');
    EXPECT_EQ(csvDecimalSign(Language::English), '.');
}

TEST(ParamCsv, StringsFloatsAndNoDictionary)
{
    const Dictionary &sd7 = dictionary("wandfluh-sd7");
    ModuleRecord m;
    m.family = "wandfluh-sd7";
    m.values.push_back(makeValueRow(*sd7.find("hart_Tag"), std::string("VALVE1")));
    m.values.push_back(makeValueRow(*sd7.find("hart_PvValue"), 12.25));
    m.values.push_back(makeValueRow(*sd7.find("hart_PvValue"), 12.25));
    m.values.back().name = "pv";
    const auto l = lines(exportCsv(m, &sd7, {Language::German, true}));
    EXPECT_EQ(l[0].substr(0, 3), "\xEF\xBB\xBF");
    EXPECT_NE(l[3].find(";VALVE1;;VALVE1;≤ 6 Bytes;"), std::string::npos) << l[3];
    EXPECT_NE(l[4].find(";12,250;"), std::string::npos) << l[4];
    EXPECT_NE(l[4].find(";12,25;"), std::string::npos) << l[4];

    const auto bare = lines(exportCsv(m, nullptr, {Language::English}));
    EXPECT_EQ(bare[3], "hart_Tag,,,,VALVE1,,");
    EXPECT_EQ(bare[4], "hart_PvValue,,,,12.25,,");
}
