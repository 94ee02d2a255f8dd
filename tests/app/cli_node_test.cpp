// valvetune-cli over a node link covers the whole node: a 3-fold DMA-2 behind Modbus TCP (a real
// valvetune-sim process on loopback). info and read find the three modules as a scan does,
// --module narrows to one; a file read from the node holds all three; a value changed in module
// 3 of that file shows in diff and is the one value write sends, to module 3; a file with a module
// the node lacks, or without one it has, is reported and refused (exit 2, nothing sent).
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"
#include "sim_process.h"

#include <QFile>
#include <QTemporaryDir>
#include <fstream>

namespace vt::clitest {
namespace {

using cli::kExitOk;
using cli::kExitUsage;

class CliNode : public CliDevice
{
protected:
    void SetUp() override
    {
        CliDevice::SetUp();
        ASSERT_TRUE(m_dir.isValid());
        m_tcp = m_sim.listening();
        ASSERT_TRUE(m_tcp.startsWith("127.0.0.1:")) << m_sim.stderrText().toStdString();
    }

    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    CliRun node(QStringList args) const { return cli(args << "--tcp" << m_tcp); }

    // The file at `from` with `edit` applied, saved as `to`.
    template<typename Edit> void rewrite(const QString &from, const QString &to, Edit edit) const
    {
        std::ifstream in(from.toStdString());
        auto doc = nlohmann::json::parse(in, nullptr, false);
        ASSERT_FALSE(doc.is_discarded());
        edit(doc);
        std::ofstream(to.toStdString()) << doc.dump(1);
    }

    static void setRaw(nlohmann::json &module, const std::string &name, int raw)
    {
        for (auto &value : module["values"])
            if (value["name"] == name) {
                value["raw"] = raw;
                value.erase("display");
                return;
            }
        ADD_FAILURE() << name << " is not in the file";
    }

    simtest::Sim m_sim{{"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0"}};
    QString m_tcp;
    QTemporaryDir m_dir;
};

TEST_F(CliNode, InfoNamesEveryModuleAndModuleNarrowsToOne)
{
    const CliRun all = node({"info"});
    ASSERT_EQ(all.code, kExitOk) << what(all);
    EXPECT_TRUE(all.says(", modbus-tcp, modules 1, 2, 3\n")) << all.out;
    for (const char *line :
         {"module 1: dma-pn-v51 V51.00, mode 3 — ", "module 2: dma-pn-v51 V51.00, mode 3 — ",
          "module 3: dma-pn-v51 V51.00, mode 3 — "})
        EXPECT_TRUE(all.says(line)) << all.out;

    const CliRun one = node({"--json", "info", "--module", "2"});
    ASSERT_EQ(one.code, kExitOk) << what(one);
    ASSERT_EQ(one.json()["modules"].size(), 1u);
    EXPECT_EQ(one.json()["modules"][0]["address"], 2);
    EXPECT_EQ(one.json()["connection"], "tcp " + m_tcp.toStdString() + ", modbus-tcp, module 2");
}

TEST_F(CliNode, ReadWriteAndDiffCoverEveryModule)
{
    const QString file = path("node.vtpar");
    const CliRun read = node({"read", "--out", file});
    ASSERT_EQ(read.code, kExitOk) << what(read);
    EXPECT_TRUE(read.says(" settings of 3 module(s) to ")) << read.out;
    std::ifstream in(file.toStdString());
    const auto saved = nlohmann::json::parse(in, nullptr, false);
    ASSERT_EQ(saved["modules"].size(), 3u) << saved.dump();
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(saved["modules"][i]["address"], i + 1);
        EXPECT_EQ(saved["modules"][i]["family"], "dma-pn-v51");
        EXPECT_GT(saved["modules"][i]["values"].size(), 100u);
    }

    const QString changed = path("changed.vtpar");
    rewrite(file, changed, [](nlohmann::json &doc) { setRaw(doc["modules"][2], "C1.07", 1500); });
    const CliRun diff = node({"--json", "diff", changed});
    ASSERT_EQ(diff.code, kExitOk) << what(diff);
    const auto compared = diff.json();
    EXPECT_EQ(compared["equal"], false);
    ASSERT_EQ(compared["modules"].size(), 3u);
    EXPECT_TRUE(compared["modules"][0]["differences"].empty());
    EXPECT_TRUE(compared["modules"][1]["differences"].empty());
    ASSERT_EQ(compared["modules"][2]["differences"].size(), 1u);
    EXPECT_EQ(compared["modules"][2]["differences"][0]["name"], "C1.07");
    EXPECT_EQ(compared["modules"][2]["differences"][0]["file"]["raw"], 1500);
    EXPECT_TRUE(compared["unmatched"].empty());

    const CliRun write = node({"--json", "write", changed});
    ASSERT_EQ(write.code, kExitOk) << what(write);
    const auto written = write.json();
    ASSERT_EQ(written["modules"].size(), 3u);
    EXPECT_TRUE(written["modules"][0]["changes"].empty());
    EXPECT_TRUE(written["modules"][1]["changes"].empty());
    const auto &changes = written["modules"][2]["changes"];
    ASSERT_EQ(changes.size(), 1u) << changes.dump();
    EXPECT_EQ(written["modules"][2]["address"], 3);
    EXPECT_EQ(changes[0]["name"], "C1.07");
    EXPECT_EQ(changes[0]["status"], "verified");
    EXPECT_EQ(node({"get", "--module", "3", "C1.07"}).out, "C1.07          1.500 V\n");
    EXPECT_EQ(node({"get", "--module", "1", "C1.07"}).out, "C1.07          0.000 V\n");
    EXPECT_EQ(node({"--json", "diff", changed}).json()["equal"], true);
    EXPECT_EQ(node({"--json", "diff", file}).json()["modules"][2]["differences"].size(), 1u);
}

// A file of four modules against three: module 4 is named; write sends nothing (module 3's
// change stays off the node); diff still compares the three and lists module 4.
TEST_F(CliNode, AModuleTheNodeLacksIsReportedAndNothingIsSent)
{
    const QString file = path("node.vtpar");
    ASSERT_EQ(node({"read", "--out", file}).code, kExitOk);
    const QString four = path("four.vtpar");
    rewrite(file, four, [](nlohmann::json &doc) {
        setRaw(doc["modules"][2], "C1.07", 2000);
        auto extra = doc["modules"][2];
        extra["address"] = 4;
        doc["modules"].push_back(extra);
    });

    const CliRun write = node({"write", four});
    EXPECT_EQ(write.code, kExitUsage) << what(write);
    EXPECT_EQ(write.errLines(), 1) << write.err;
    EXPECT_TRUE(write.complains("the file's module 4 (dma-pn-v51) is not on the node"))
        << write.err;
    EXPECT_TRUE(write.complains("nothing was sent")) << write.err;
    EXPECT_TRUE(write.out.empty()) << write.out;
    EXPECT_EQ(node({"get", "--module", "3", "C1.07"}).out, "C1.07          0.000 V\n");

    const CliRun diff = node({"diff", four});
    EXPECT_EQ(diff.code, kExitUsage) << what(diff);
    EXPECT_TRUE(diff.says("module 4: in the file (dma-pn-v51), not on the node\n")) << diff.out;
    EXPECT_TRUE(diff.says("module 3: dma-pn-v51 V51.00, mode 3: 1 difference")) << diff.out;
    EXPECT_TRUE(diff.complains("module 4")) << diff.err;

    const CliRun json = node({"--json", "diff", four});
    EXPECT_EQ(json.code, kExitUsage) << what(json);
    EXPECT_EQ(json.json()["unmatched"],
              nlohmann::json::parse(R"([{"address": 4, "family": "dma-pn-v51", "in": "file"}])"));

    // --module takes the one module out of the file.
    const CliRun one = node({"write", four, "--module", "3"});
    ASSERT_EQ(one.code, kExitOk) << what(one);
    EXPECT_TRUE(one.says("module 3: dma-pn-v51 V51.00, mode 3: 1 change, ")) << one.out;
}

// The reverse: a file without module 3 is no file for the whole node.
TEST_F(CliNode, AModuleTheFileLacksIsReported)
{
    const QString file = path("node.vtpar");
    ASSERT_EQ(node({"read", "--out", file}).code, kExitOk);
    const QString two = path("two.vtpar");
    rewrite(file, two, [](nlohmann::json &doc) {
        setRaw(doc["modules"][1], "C1.07", 700);
        doc["modules"].erase(2);
    });
    const CliRun write = node({"write", two});
    EXPECT_EQ(write.code, kExitUsage) << what(write);
    EXPECT_TRUE(write.complains("the node's module 3 (dma-pn-v51) is not in the file"))
        << write.err;
    EXPECT_EQ(node({"get", "--module", "2", "C1.07"}).out, "C1.07          0.000 V\n");

    const CliRun diff = node({"diff", two});
    EXPECT_EQ(diff.code, kExitUsage) << what(diff);
    EXPECT_TRUE(diff.says("module 3: dma-pn-v51 V51.00, mode 3: on the node, not in the file\n"))
        << diff.out;
}

} // namespace
} // namespace vt::clitest
