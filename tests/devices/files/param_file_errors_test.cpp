// A damaged, foreign, oversized or newer parameter file is a typed error with a place and a
// message in both languages, never a crash (STYLE.md rule 12: never crash on a bad file).
#include "file_test_support.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::files;

namespace {

FileError errorOf(const std::string &text)
{
    auto r = parseParamFile(text);
    if (r.ok())
        throw std::runtime_error("parsed, expected an error: " + text);
    EXPECT_TRUE(r.error().message.complete());
    EXPECT_TRUE(r.error().text().complete());
    return r.error();
}

// A one-module file whose row is `row` (JSON text).
std::string withRow(const std::string &row)
{
    return R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": [)"
           R"({"address": 1, "family": "opat", "values": [)" +
           row + "]}]}";
}

std::string withModule(const std::string &module)
{
    return R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": [)" + module + "]}";
}

} // namespace

TEST(ParamFileErrors, TruncatedFilesAreSyntaxErrorsWithALine)
{
    ParamFile f;
    f.modules.push_back(vt::dev::files::test::moduleFromDefaults("dma-pb-v22", 1, "22.01", "2"));
    const std::string text = writeParamFile(f);
    const FileError e = errorOf(text.substr(0, text.size() / 2));
    EXPECT_EQ(e.code, FileErrc::Syntax);
    EXPECT_GT(e.line, 10u);
    EXPECT_NE(e.text().de.find("Zeile "), std::string::npos);
    // Every prefix of a small file is refused cleanly, none is accepted half-read.
    const std::string small =
        withRow(R"({"name": "C1.07", "id": 48, "raw": 1000, "display": "1.000 V"})");
    for (std::size_t n = 0; n < small.size(); ++n)
        EXPECT_FALSE(parseParamFile(small.substr(0, n)).ok()) << n;
    EXPECT_TRUE(parseParamFile(small).ok());
}

TEST(ParamFileErrors, WrongTypesNameTheKey)
{
    struct Case
    {
        std::string text;
        FileErrc code;
        std::string location;
    };
    const Case cases[] = {
        {withRow(R"({"name": "C1.07", "raw": true})"), FileErrc::WrongType,
         "/modules/0/values/0/raw"},
        {withRow(R"({"name": "C1.07", "raw": null})"), FileErrc::WrongType,
         "/modules/0/values/0/raw"},
        {withRow(R"({"name": "C1.07", "raw": [1]})"), FileErrc::WrongType,
         "/modules/0/values/0/raw"},
        {withRow(R"({"name": "C1.07", "raw": {"number": "nan"}})"), FileErrc::BadValue,
         "/modules/0/values/0/raw/number"},
        {withRow(R"({"name": 7, "raw": 1})"), FileErrc::WrongType, "/modules/0/values/0/name"},
        {withRow(R"({"name": "C1.07", "id": "48", "raw": 1})"), FileErrc::WrongType,
         "/modules/0/values/0/id"},
        {withRow(R"({"name": "C1.07", "id": 48.5, "raw": 1})"), FileErrc::WrongType,
         "/modules/0/values/0/id"},
        {withRow(R"({"name": "C1.07", "id": 4294967296, "raw": 1})"), FileErrc::BadValue,
         "/modules/0/values/0/id"},
        {withRow(R"({"name": "C1.07", "raw": 1, "display": 1})"), FileErrc::WrongType,
         "/modules/0/values/0/display"},
        {withRow(R"({"name": "C1.07"})"), FileErrc::MissingKey, "/modules/0/values/0"},
        {withRow(R"({"name": "", "raw": 1})"), FileErrc::BadValue, "/modules/0/values/0/name"},
        {withRow(R"({"name": "C1.07", "raw": 9007199254740993})"), FileErrc::BadValue,
         "/modules/0/values/0/raw"},
        {withRow(R"([1, 2])"), FileErrc::WrongType, "/modules/0/values/0"},
        {withRow(R"({"name": "C1.07", "raw": 1}, {"name": "C1.07", "raw": 2})"),
         FileErrc::Duplicate, "/modules/0/values/1/name"},
        {withModule(R"({"address": "1", "family": "opat", "values": []})"), FileErrc::WrongType,
         "/modules/0/address"},
        {withModule(R"({"address": 256, "family": "opat", "values": []})"), FileErrc::BadValue,
         "/modules/0/address"},
        {withModule(R"({"address": -1, "family": "opat", "values": []})"), FileErrc::BadValue,
         "/modules/0/address"},
        {withModule(R"({"address": 1, "values": []})"), FileErrc::MissingKey, "/modules/0"},
        {withModule(R"({"address": 1, "family": "opat", "values": {}})"), FileErrc::WrongType,
         "/modules/0/values"},
        {withModule(R"({"address": 1, "family": "opat", "mode": 3, "values": []})"),
         FileErrc::WrongType, "/modules/0/mode"},
        {withModule(
             R"({"address": 1, "family": "opat", "values": []}, {"address": 1, "family": "opat", "values": []})"),
         FileErrc::Duplicate, "/modules/1/address"},
        {withModule(R"("module")"), FileErrc::WrongType, "/modules/0"},
        {R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": {}})",
         FileErrc::WrongType, "/modules"},
        {R"({"format": "valvetune-parameters", "formatVersion": 1})", FileErrc::MissingKey, ""},
        {R"({"format": "valvetune-parameters", "formatVersion": "1", "modules": []})",
         FileErrc::WrongType, "/formatVersion"},
        {R"({"format": "valvetune-parameters", "formatVersion": 0, "modules": []})",
         FileErrc::BadValue, "/formatVersion"},
        {R"({"format": "valvetune-parameters", "formatVersion": 1, "tool": 5, "modules": []})",
         FileErrc::WrongType, "/tool"},
    };
    for (const Case &c : cases) {
        const FileError e = errorOf(c.text);
        EXPECT_EQ(e.code, c.code) << c.text << "\n" << e.text().en;
        EXPECT_EQ(e.location, c.location) << c.text << "\n" << e.text().en;
    }
}

TEST(ParamFileErrors, OtherJsonIsNotAParameterFile)
{
    for (const char *text :
         {"[]", "42", "\"x\"", "{}", R"({"schema": 1, "family": "opat", "parameters": []})",
          R"({"format": "something-else", "formatVersion": 1, "modules": []})"})
        EXPECT_EQ(errorOf(text).code, FileErrc::NotAParamFile) << text;
    EXPECT_EQ(errorOf("").code, FileErrc::Syntax);
    EXPECT_EQ(errorOf("\xEF\xBB\xBF{").code, FileErrc::Syntax);
}

TEST(ParamFileErrors, ANewerMajorVersionIsRefusedWithAClearMessage)
{
    const FileError e =
        errorOf(R"({"format": "valvetune-parameters", "formatVersion": 2, "modules": "changed"})");
    EXPECT_EQ(e.code, FileErrc::NewerVersion);
    EXPECT_EQ(e.location, "/formatVersion");
    EXPECT_NE(e.message.en.find("newer ValveTune (file format 2)"), std::string::npos)
        << e.message.en;
    EXPECT_NE(e.message.de.find("bitte ValveTune aktualisieren"), std::string::npos);
    EXPECT_EQ(
        errorOf(R"({"format": "valvetune-parameters", "formatVersion": 18446744073709551615})")
            .code,
        FileErrc::BadValue);
}

TEST(ParamFileErrors, LimitsOnSizeDepthAndCounts)
{
    std::string big = withRow(R"({"name": "C1.07", "raw": 1})");
    big.append(kMaxFileBytes, ' ');
    EXPECT_EQ(errorOf(big).code, FileErrc::TooLarge);

    const std::string deep = withRow(R"({"name": "C1.07", "raw": 1, "x": )" +
                                     std::string(5000, '[') + std::string(5000, ']') + "}");
    const FileError d = errorOf(deep);
    EXPECT_EQ(d.code, FileErrc::TooDeep);
    EXPECT_EQ(d.line, 1u);
    // Brackets inside strings do not count.
    EXPECT_TRUE(parseParamFile(withRow(R"({"name": "C1.07", "raw": ")" + std::string(100, '[') +
                                       "\\\"" + R"("})"))
                    .ok());

    std::string modules;
    for (std::size_t i = 0; i <= kMaxModules; ++i)
        modules += (i ? "," : "") + std::string(R"({"address": )") + std::to_string(i) +
                   R"(, "family": "opat", "values": []})";
    const FileError m = errorOf(withModule(modules));
    EXPECT_EQ(m.code, FileErrc::TooMany);
    EXPECT_EQ(m.location, "/modules");

    std::string rows;
    for (std::size_t i = 0; i <= kMaxRows; ++i)
        rows +=
            (i ? "," : "") + std::string(R"({"name": "r)") + std::to_string(i) + R"(", "raw": 0})";
    EXPECT_EQ(errorOf(withRow(rows)).code, FileErrc::TooMany);
}
