// Opening a file from another version: a DMA PROFIBUS V22 file opened against a V32
// module reports, row by row, what did not map, and why (DMA Profibus Anleitung §7: E18 from
// V32.09, C1.33/C2.33 from V32.10a).
#include "file_test_support.h"
#include "files/param_file_map.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::files;
using vt::dev::files::test::dictionary;
using vt::dev::files::test::moduleFromDefaults;
using vt::dev::files::test::Rows;

namespace {

const RowMapping *rowNamed(const MapReport &r, const std::string &name)
{
    const auto it = std::find_if(r.rows.begin(), r.rows.end(),
                                 [&](const RowMapping &m) { return m.name == name; });
    return it == r.rows.end() ? nullptr : &*it;
}

std::vector<std::string> namesWith(const MapReport &r, MapStatus status)
{
    std::vector<std::string> out;
    for (const RowMapping &m : r.rows)
        if (m.status == status)
            out.push_back(m.name);
    return out;
}

ValueRow &rowOf(ModuleRecord &m, const std::string &name)
{
    for (ValueRow &row : m.values)
        if (row.name == name)
            return row;
    throw std::runtime_error("no row " + name);
}

} // namespace

TEST(ParamFileMap, AFileOfTheSameFamilyMapsCleanly)
{
    const ModuleRecord m = moduleFromDefaults("dma-pb-v32", 1, "32.10", "3");
    const MapReport r = mapModule(m, dictionary("dma-pb-v32"));
    EXPECT_TRUE(r.clean()) << r.summary().en;
    EXPECT_EQ(r.count(MapStatus::Mapped), m.values.size());
    EXPECT_TRUE(r.problems().empty());
    EXPECT_EQ(r.summary().en, std::to_string(m.values.size()) + " mapped");
    for (const RowMapping &row : r.rows)
        EXPECT_EQ(row.meta->name, m.values[row.row].name);
}

TEST(ParamFileMap, V22FileOpenedAgainstAV32Module)
{
    ModuleRecord m = moduleFromDefaults("dma-pb-v22", 2, "22.05", "2");
    rowOf(m, "C1.07").raw = 12000.0;             // above 9.999 V
    rowOf(m, "E22").raw = std::string("3");      // text for a number row
    rowOf(m, "C1.00").raw = 1.5;                 // a fraction for an enum row
    rowOf(m, "C2.07").name = "C2.07 (old name)"; // renamed: found again by ID
    m.values.push_back(
        {"X9.99", 4000, {}, {}, {}, 7.0, {}, nlohmann::json::object()}); // unknown everywhere
    m.values.push_back(
        {"C1.99", 48, {}, {}, {}, 7.0, {}, nlohmann::json::object()}); // ID of C1.07, also in the
                                                                       // file

    const MapReport r = mapModule(m, dictionary("dma-pb-v32"), MapTarget{"32.10", "3"});
    ASSERT_EQ(r.notes.size(), 2u);
    EXPECT_NE(r.notes[0].en.find("written for dma-pb-v22; its values are mapped onto dma-pb-v32"),
              std::string::npos);
    EXPECT_NE(
        r.notes[1].en.find("saved from version 22.05 in mode 2; this module runs 32.10 in mode 3"),
        std::string::npos)
        << r.notes[1].en;
    EXPECT_FALSE(r.clean());

    // The rows V32 has and V22 had not: the module keeps its own values there.
    EXPECT_EQ(namesWith(r, MapStatus::Missing),
              (std::vector<std::string>{"E18", "C1.33", "C2.33"}));
    const RowMapping *e18 = rowNamed(r, "E18");
    EXPECT_EQ(e18->row, RowMapping::kNoRow);
    EXPECT_EQ(e18->reason.de, "E18 fehlt in der Datei: das Modul behält seinen Wert");

    EXPECT_EQ(namesWith(r, MapStatus::OutOfRange), std::vector<std::string>{"C1.07"});
    EXPECT_EQ(rowNamed(r, "C1.07")->reason.en,
              "C1.07: above the maximum 9.999 V (range 0.000 V … 9.999 V)");
    EXPECT_EQ(namesWith(r, MapStatus::TypeMismatch), (std::vector<std::string>{"C1.00", "E22"}));
    EXPECT_EQ(rowNamed(r, "E22")->reason.en, "E22 holds a number; the file has a text");
    EXPECT_EQ(rowNamed(r, "C1.00")->reason.en, "C1.00 takes whole numbers; the file has 1.5");

    const RowMapping *renamed = rowNamed(r, "C2.07 (old name)");
    ASSERT_NE(renamed, nullptr);
    EXPECT_EQ(renamed->status, MapStatus::MappedByAddress);
    EXPECT_EQ(renamed->meta->name, "C2.07");
    EXPECT_TRUE(renamed->applies());
    EXPECT_EQ(renamed->reason.en, "C2.07 (old name) is named C2.07 in dma-pb-v32 (same " +
                                      renamed->meta->addressText() + ")");

    EXPECT_EQ(namesWith(r, MapStatus::Unknown), (std::vector<std::string>{"X9.99", "C1.99"}));
    EXPECT_EQ(rowNamed(r, "X9.99")->reason.en,
              "X9.99 is not in dma-pb-v32: kept in the file, not applied");
    EXPECT_EQ(rowNamed(r, "C1.99")->reason.en,
              "C1.99: its ID 0x30 belongs to C1.07, which the file sets as well");

    const std::size_t problems = 3 + 1 + 2 + 1 + 2;
    EXPECT_EQ(r.problems().size(), problems);
    EXPECT_EQ(r.count(MapStatus::Mapped), m.values.size() - (problems - 3));
    EXPECT_EQ(
        r.summary().en,
        std::to_string(r.count(MapStatus::Mapped)) +
            " mapped, 1 mapped by address, 2 unknown, 1 out of range, 2 type mismatch, 3 missing");
    EXPECT_NE(r.summary().de.find("3 fehlt"), std::string::npos);
    for (const RowMapping *p : r.problems())
        EXPECT_TRUE(p->reason.complete()) << p->name;
}

TEST(ParamFileMap, WithoutATargetTheFileSaysWhichVersionAndMode)
{
    // The file's own version (22) and mode (2) decide: V32-only rows are not missing, and the
    // report says that dma-pb-v32 does not describe V22 in mode 2.
    const ModuleRecord m = moduleFromDefaults("dma-pb-v22", 1, "22.05", "2");
    const MapReport r = mapModule(m, dictionary("dma-pb-v32"));
    ASSERT_EQ(r.notes.size(), 3u);
    EXPECT_EQ(r.notes[1].en, "dma-pb-v32 describes software version 31, 32, not V22");
    EXPECT_EQ(r.notes[2].de, "dma-pb-v32 beschreibt Modus 3, 4, 6, 8, nicht Modus 2");
    EXPECT_EQ(r.count(MapStatus::Missing), 0u);
    EXPECT_EQ(r.count(MapStatus::Mapped), m.values.size());
}

TEST(ParamFileMap, RowsOfANewerVersionAreNotApplicableToAnOlderModule)
{
    // A V32.10 file onto a V31 module: E18, C1.33, C2.33 exist only in V32.
    const ModuleRecord m = moduleFromDefaults("dma-pb-v32", 1, "32.10", "3");
    const MapReport r = mapModule(m, dictionary("dma-pb-v32"), MapTarget{"31.02", "3"});
    EXPECT_EQ(namesWith(r, MapStatus::NotApplicable),
              (std::vector<std::string>{"E18", "C1.33", "C2.33"}));
    EXPECT_EQ(rowNamed(r, "E18")->reason.en, "E18 exists only in software version 32, not in V31");
    EXPECT_FALSE(rowNamed(r, "E18")->applies());
}

TEST(ParamFileMap, WandfluhRowsFallBackToIndPnuAndStringsAreChecked)
{
    const Dictionary &sd7 = dictionary("wandfluh-sd7");
    ModuleRecord m = moduleFromDefaults("wandfluh-sd7", 0, "", "vpoc", Rows::All);
    rowOf(m, "db_DeviceMode").name = "db_DevMode";
    rowOf(m, "hart_Tag").raw = std::string("TOO-LONG-TAG");
    rowOf(m, "hart_PvValue").raw = std::nan(""); // read-only live value: not range-checked
    const MapReport r = mapModule(m, sd7);
    EXPECT_EQ(rowNamed(r, "db_DevMode")->status, MapStatus::MappedByAddress);
    EXPECT_EQ(rowNamed(r, "db_DevMode")->meta->name, "db_DeviceMode");
    EXPECT_EQ(rowNamed(r, "hart_PvValue")->status, MapStatus::Mapped);
    const RowMapping *tag = rowNamed(r, "hart_Tag");
    EXPECT_EQ(tag->status, MapStatus::OutOfRange);
    EXPECT_EQ(tag->reason.en, "hart_Tag: the text has 12 bytes, the row holds 6");
    bool byAddress = true;
    EXPECT_EQ(findMeta(sd7, m.values.front(), &byAddress), &sd7.params.front());
    EXPECT_FALSE(byAddress);
}

// An older file saved every row it read, set values and display values included. It opens as
// before, but the process and live values are named in a note and never written (DMA Profinet
// manual §4.5.3: A1.01 and A1.02 are the "Process Value1/2" of the cyclic telegram; §6: d-values
// are read only).
TEST(ParamFileMap, ProcessAndLiveValuesOfAnOldFileAreIgnoredForWriting)
{
    ModuleRecord m = moduleFromDefaults("dma-pn-v51", 1, "51.02", "3", Rows::All);
    rowOf(m, "A1.01").raw = 2000.0;
    rowOf(m, "A2.01").raw = 99999.0; // out of range, but never written: not a reason to refuse
    const MapReport r = mapModule(m, dictionary("dma-pn-v51"));

    ASSERT_EQ(r.notes.size(), 2u);
    EXPECT_EQ(r.notes[0].en, "process values, not settings, kept in the file and ignored for "
                             "writing: A1.01, A1.02, A2.01, A2.02, 0xB0");
    EXPECT_EQ(r.notes[0].de, "Prozesswerte, keine Einstellungen, bleiben in der Datei und werden "
                             "nicht geschrieben: A1.01, A1.02, A2.01, A2.02, 0xB0");
    EXPECT_EQ(r.notes[1].en.rfind("live values, not settings, kept in the file and ignored for "
                                  "writing: d1.01, d1.02, ",
                                  0),
              0u)
        << r.notes[1].en;
    EXPECT_NE(r.notes[1].en.find("So.in"), std::string::npos);
    EXPECT_FALSE(r.clean());

    std::vector<std::string> ignored;
    for (const RowMapping *row : r.ignoredForWriting())
        ignored.push_back(row->name);
    EXPECT_EQ(ignored.size(), 21u + 1u + 5u); // d1.01..d2.13, So.in; A1.01..A2.02, 0xB0
    EXPECT_EQ(rowNamed(r, "A2.01")->status, MapStatus::Mapped);
    EXPECT_TRUE(rowNamed(r, "A1.01")->ignoredForWriting);
    EXPECT_FALSE(rowNamed(r, "C1.07")->ignoredForWriting);
    EXPECT_FALSE(rowNamed(r, "S1.01")->ignoredForWriting); // a stored internal set value
    EXPECT_TRUE(r.problems().empty());
}

// A file of this version holds settings only; the set values it leaves out are not "missing".
TEST(ParamFileMap, ProcessValuesAreNeverMissing)
{
    const ModuleRecord m = moduleFromDefaults("dma-pb-v32", 1, "32.10", "3");
    EXPECT_EQ(m.find("A1.01"), nullptr);
    EXPECT_EQ(m.find("d1.11"), nullptr);
    ASSERT_NE(m.find("E17"), nullptr);
    const MapReport r = mapModule(m, dictionary("dma-pb-v32"));
    EXPECT_EQ(r.count(MapStatus::Missing), 0u);
    EXPECT_TRUE(r.clean()) << r.summary().en;
}
