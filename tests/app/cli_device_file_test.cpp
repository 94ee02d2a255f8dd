// valvetune-cli read --out / diff / write golden tests (docs/FILE-FORMAT.md):
// a file read from the device shows no difference, a changed parameter shows as exactly that row,
// write --dry-run lists it, write restores it (changed only, verified); a file of another family
// or with a value out of range is refused whole.
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"

#include <QFile>
#include <QTemporaryDir>

namespace vt::clitest {
namespace {

using cli::kExitOk;
using cli::kExitUsage;

class CliDeviceFile : public CliDevice
{
protected:
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    QTemporaryDir m_dir;
};

TEST_F(CliDeviceFile, ReadDiffSetDiffWriteRoundTrip)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = path("dma.vtpar");
    const QStringList sim{"--sim", "dma-pn-v51"};

    const CliRun read = cli(QStringList{"read", "--out", file} + sim);
    ASSERT_EQ(read.code, kExitOk) << what(read);
    EXPECT_TRUE(read.says(" settings of 1 module(s) to ")) << read.out;
    QFile saved(file);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    const QByteArray text = saved.readAll();
    EXPECT_TRUE(text.contains("\"format\": \"valvetune-parameters\""))
        << text.left(200).toStdString();
    EXPECT_TRUE(
        text.contains("{\"name\": \"C1.07\", \"id\": 48, \"raw\": 0, \"display\": \"0.000 V\"}"));

    const CliRun same = cli(QStringList{"diff", file} + sim);
    ASSERT_EQ(same.code, kExitOk) << what(same);
    EXPECT_TRUE(same.says("module 1: dma-pn-v51 V51.00, mode 3: no differences (")) << same.out;
    const CliRun sameJson = cli(QStringList{"--json", "diff", file} + sim);
    EXPECT_EQ(sameJson.json()["equal"], true) << sameJson.out;
    EXPECT_GT(sameJson.json()["modules"][0]["compared"].get<int>(), 100);

    ASSERT_EQ(cli(QStringList{"set", "C1.07=1.000"} + sim).code, kExitOk);

    const CliRun changed = cli(QStringList{"diff", file} + sim);
    ASSERT_EQ(changed.code, kExitOk) << what(changed);
    EXPECT_TRUE(changed.says(": 1 difference (")) << changed.out;
    EXPECT_TRUE(changed.says("  C1.07  file 0.000 V, device 1.000 V\n")) << changed.out;
    const CliRun changedJson = cli(QStringList{"--json", "diff", file} + sim);
    const auto doc = changedJson.json();
    EXPECT_EQ(doc["equal"], false);
    ASSERT_EQ(doc["modules"][0]["differences"].size(), 1u) << changedJson.out;
    EXPECT_EQ(doc["modules"][0]["differences"][0],
              (nlohmann::json{{"name", "C1.07"},
                              {"file", {{"raw", 0}, {"display", "0.000 V"}}},
                              {"device", {{"raw", 1000}, {"display", "1.000 V"}}}}));

    const CliRun dry = cli(QStringList{"write", file, "--dry-run"} + sim);
    ASSERT_EQ(dry.code, kExitOk) << what(dry);
    EXPECT_TRUE(dry.says(": 1 would change, ")) << dry.out;
    EXPECT_TRUE(dry.says("  C1.07          1.000 V -> 0.000 V\n")) << dry.out;
    const CliRun dryJson = cli(QStringList{"--json", "write", file, "--dry-run"} + sim);
    EXPECT_EQ(dryJson.json()["dry_run"], true);
    ASSERT_EQ(dryJson.json()["modules"][0]["changes"].size(), 1u) << dryJson.out;
    EXPECT_EQ(dryJson.json()["modules"][0]["changes"][0]["status"], "pending");
    // A dry run changes nothing.
    EXPECT_EQ(cli(QStringList{"get", "C1.07"} + sim).out, "C1.07          1.000 V\n");

    const CliRun write = cli(QStringList{"--json", "write", file} + sim);
    ASSERT_EQ(write.code, kExitOk) << what(write);
    const auto written = write.json();
    EXPECT_EQ(written["complete"], true);
    const auto &module = written["modules"][0];
    ASSERT_EQ(module["changes"].size(), 1u) << write.out; // only the changed row was sent
    EXPECT_EQ(module["changes"][0]["name"], "C1.07");
    EXPECT_EQ(module["changes"][0]["status"], "verified");
    EXPECT_EQ(module["changes"][0]["read_back"]["raw"], 0);
    EXPECT_GT(module["unchanged"].get<int>(), 100);

    EXPECT_EQ(cli(QStringList{"get", "C1.07"} + sim).out, "C1.07          0.000 V\n");
    EXPECT_EQ(cli(QStringList{"--json", "diff", file} + sim).json()["equal"], true);
    const CliRun again = cli(QStringList{"write", file} + sim);
    ASSERT_EQ(again.code, kExitOk) << what(again);
    EXPECT_TRUE(again.says(": 0 changes, ")) << again.out;
}

// A whole fold in one file: every module goes back to its own address.
TEST_F(CliDeviceFile, AFoldRoundTripsModuleByModule)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = path("opat.vtpar");
    const QStringList sim{"--sim", "opat:3"};
    ASSERT_EQ(cli(QStringList{"read", "--out", file} + sim).code, kExitOk);
    ASSERT_EQ(cli(QStringList{"set", "--module", "2", "C1.07=0.500"} + sim).code, kExitOk);

    const CliRun diff = cli(QStringList{"--json", "diff", file} + sim);
    ASSERT_EQ(diff.code, kExitOk) << what(diff);
    const auto modules = diff.json()["modules"];
    ASSERT_EQ(modules.size(), 3u);
    EXPECT_TRUE(modules[0]["differences"].empty());
    EXPECT_TRUE(modules[1]["differences"].empty());
    ASSERT_EQ(modules[2]["differences"].size(), 1u);
    EXPECT_EQ(modules[2]["differences"][0]["name"], "C1.07");

    const CliRun write = cli(QStringList{"write", file, "--module", "2"} + sim);
    ASSERT_EQ(write.code, kExitOk) << what(write);
    EXPECT_TRUE(write.says("module 2: opat V31.00, mode 3: 1 change, ")) << write.out;
    EXPECT_EQ(cli(QStringList{"--json", "diff", file} + sim).json()["equal"], true);
}

TEST_F(CliDeviceFile, AFileOfAnotherFamilyIsRefused)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = path("opat.vtpar");
    ASSERT_EQ(cli({"read", "--sim", "opat", "--out", file}).code, kExitOk);
    for (const char *command : {"write", "diff"}) {
        const CliRun r = cli({command, file, "--sim", "dma-pn-v51"});
        EXPECT_EQ(r.code, kExitUsage) << command << '\n' << what(r);
        EXPECT_EQ(r.errLines(), 1) << r.err;
        EXPECT_TRUE(r.complains("is for opat; module 1: dma-pn-v51")) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

// A hand-edited file with a value out of range: nothing of it is written.
TEST_F(CliDeviceFile, AValueOutOfRangeRefusesTheWholeFile)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = path("bad.vtpar");
    QFile out(file);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(R"({"format": "valvetune-parameters", "formatVersion": 1, "modules": [
        {"address": 1, "family": "dma-pn-v51", "values": [
            {"name": "r1.01", "id": 27, "raw": 150},
            {"name": "C1.07", "id": 48, "raw": 12000}]}]})");
    out.close();
    const CliRun r = cli({"write", file, "--sim", "dma-pn-v51"});
    EXPECT_EQ(r.code, kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("nothing was sent")) << r.err;
    EXPECT_EQ(cli({"get", "r1.01", "--sim", "dma-pn-v51"}).out, "r1.01          0 ms\n");

    const CliRun broken = cli({"diff", path("missing.vtpar"), "--sim", "dma-pn-v51"});
    EXPECT_EQ(broken.code, kExitUsage) << what(broken);
}

} // namespace
} // namespace vt::clitest
