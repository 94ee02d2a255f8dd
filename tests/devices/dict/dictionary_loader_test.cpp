// A broken dictionary is a clear error naming file and row.
#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

std::string header(const std::string &family, const std::string &extra = {})
{
    return R"({"schema":1,"family":")" + family +
           R"(","title":{"en":"T","de":"T"},"vendor":"HCS","protocol":"hcs","versions":["1"],"modes":["1"],)" +
           extra;
}

std::string row(const std::string &name, int id, const std::string &extra = {})
{
    return R"({"name":")" + name + R"(","id":)" + std::to_string(id) +
           R"(,"block":"C","access":"rw","type":"int16","min":0,"max":100,"label":{"en":"L","de":"L"})" +
           extra + "}";
}

std::vector<std::string> errors(const std::vector<DictionaryFile> &files)
{
    std::vector<std::string> out;
    auto r = loadDictionaries(files);
    if (!r.ok())
        for (const auto &e : r.error())
            out.push_back(e.text());
    return out;
}

} // namespace

TEST(DictionaryLoader, ExtendsMergesKindsAndRemoves)
{
    const std::vector<DictionaryFile> files = {
        {"base.json",
         header(
             "base",
             R"("abstract":true,"scales":{"milli":{"factor":0.001,"decimals":3}},)"
             R"("types":{"volt":{"type":"int16","scale":"milli","unit":"V","min":-9999,"max":9999}},)"
             R"("parameters":[)" +
                 row("C1.01", 1) + "," + row("C1.02", 2, R"(,"kind":"volt")") + "," +
                 row("C1.03", 3) + "]}")},
        {"child.json",
         header("child", R"("extends":"base","parameters":[{"name":"C1.01","max":50},)" +
                             row("C1.04", 4) + R"(],"remove":["C1.03"]})")}};
    auto r = loadDictionaries(files);
    ASSERT_TRUE(r.ok()) << r.error().front().text();
    EXPECT_EQ(r->families(), std::vector<std::string>{"child"}); // the abstract base is not offered
    const Dictionary *child = r->find("child");
    ASSERT_NE(child, nullptr);
    ASSERT_EQ(child->params.size(), 3u);
    EXPECT_EQ(child->params[0].name, "C1.01");
    EXPECT_EQ(child->params[0].max, 50);        // overridden key by key
    EXPECT_EQ(child->params[0].label.en, "L");  // inherited
    EXPECT_EQ(child->find("C1.02")->unit, "V"); // from the kind
    EXPECT_EQ(child->find("C1.02")->scale.factor, 0.001);
    EXPECT_EQ(child->find("C1.03"), nullptr);
    EXPECT_EQ(child->findId(4)->name, "C1.04");
}

TEST(DictionaryLoader, ErrorsNameFileAndRow)
{
    auto e = errors(
        {{"bad.json",
          header(
              "bad",
              R"("parameters":[)" + row("C1.01", 1) + "," + row("C1.01", 2) + "," +
                  row("C1.03", 1) + "," + row("C1.04", 4, R"(,"min":200)") + "," +
                  R"({"name":"C1.05","id":5,"block":"C","access":"rw","type":"int16","label":{"en":"only English"}})" +
                  "]}")}});
    ASSERT_EQ(e.size(), 4u);
    EXPECT_EQ(e[0], "bad.json, row C1.01: duplicate name");
    EXPECT_EQ(e[1], "bad.json, row C1.03: duplicate id 1");
    EXPECT_EQ(e[2], "bad.json, row C1.04: min 200 > max 100");
    EXPECT_EQ(e[3], "bad.json, row C1.05: label has no German text");
}

TEST(DictionaryLoader, StructuralErrors)
{
    EXPECT_EQ(errors({{"x.json", "{ not json"}}),
              std::vector<std::string>{"x.json: not a JSON object (syntax error)"});
    EXPECT_EQ(
        errors({{"x.json", header("y", R"("parameters":[]})")}}),
        std::vector<std::string>{"x.json: \"family\" must equal the file name without .json"});
    EXPECT_EQ(errors({{"a.json", header("a", R"("extends":"b","parameters":[]})")},
                      {"b.json", header("b", R"("extends":"a","parameters":[]})")}})
                  .front(),
              "a.json: \"extends\" forms a cycle");
    EXPECT_EQ(errors({{"k.json", header("k", R"("parameters":[)" +
                                                 row("C1.01", 1, R"(,"kind":"nope")") + "]}")}}),
              std::vector<std::string>{"k.json, row C1.01: unknown kind 'nope'"});
    // A key of the wrong JSON type is reported, not thrown.
    EXPECT_EQ(errors({{"t.json",
                       header("t", R"("parameters":[)" + row("C1.01", 1, R"(,"modes":5)") + "]}")}})
                  .size(),
              1u);
}

TEST(DictionaryLoader, EnumValuesMustBeInRangeAndTranslated)
{
    auto e = errors(
        {{"e.json",
          header(
              "e",
              R"("parameters":[)" +
                  row("C1.01", 1,
                      R"(,"enum":[{"value":0,"en":"off","de":"aus"},{"value":101,"en":"x","de":"x"},{"value":1,"en":"on"}])") +
                  "]}")}});
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0], "e.json, row C1.01: enum value 101 outside the range");
    EXPECT_EQ(e[1], "e.json, row C1.01: enum 1 has no German text");
}

// Found by fuzz_dictionary: a family-level key of the wrong JSON type must be an error, not a
// throw.
TEST(DictionaryLoader, WrongJsonTypesAtFileLevelAreErrors)
{
    const auto e = errors({{"x.json", R"({"schema":1,"family":{"milli":1},"parameters":[]})"}});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].rfind("x.json: ", 0), 0u);
}
