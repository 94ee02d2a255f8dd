// valvetune-cli and valve-moving writes (confirm_gate.h): a set value, E17 or a control word is
// written only when the person at the terminal says yes or --yes was given; without a terminal
// the command exits 2 naming module, parameter and old -> new, and the device is unchanged (read
// back to prove it). Files carry settings only: read --out leaves process and live values out,
// write lists them and never writes them (DMA Profinet manual §4.5.3 "Process Value1 = A1.01").
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"

#include <QFile>
#include <QTemporaryDir>

namespace vt::clitest {
namespace {

using cli::kExitOk;
using cli::kExitUsage;

// valvetune-cli on a terminal where the person types `answers`.
CliRun cliOnTerminal(QStringList args, const std::string &answers)
{
    args.prepend(QStringLiteral("valvetune-cli"));
    std::istringstream in(answers);
    std::ostringstream out, err;
    CliRun r;
    r.code = cli::runCli(args, out, err, cli::Console{true, &in});
    r.out = out.str();
    r.err = err.str();
    return r;
}

std::string get(const char *name, const QStringList &sim)
{
    return cli(QStringList{"get", QString::fromLatin1(name)} + sim).out;
}

class CliConfirm : public CliDevice
{
protected:
    QString writeFile(const char *name, const char *text)
    {
        const QString path = m_dir.filePath(QString::fromLatin1(name));
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
        return path;
    }

    // At the factory defaults (E17 = 0): the commissioned simulator already has E17 = 2, so
    // setting it would be "unchanged" and ask nothing.
    const QStringList m_sim{"--sim", "dma-pn-v51", "--factory"};
    QTemporaryDir m_dir;
};

TEST_F(CliConfirm, ASetValueWithoutATerminalNeedsYes)
{
    const CliRun refused = cli(QStringList{"set", "A1.01=2.000"} + m_sim);
    EXPECT_EQ(refused.code, kExitUsage) << what(refused);
    EXPECT_TRUE(refused.out.empty()) << refused.out;
    EXPECT_EQ(refused.errLines(), 1) << refused.err;
    EXPECT_TRUE(refused.complains("module 1: dma-pn-v51 V51.00, mode 3: A1.01 0.000 V -> 2.000 V"))
        << refused.err;
    EXPECT_TRUE(refused.complains("pass --yes")) << refused.err;
    EXPECT_TRUE(refused.complains("nothing was sent")) << refused.err;
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          0.000 V\n");

    const CliRun yes = cli(QStringList{"set", "--yes", "A1.01=2.000"} + m_sim);
    ASSERT_EQ(yes.code, kExitOk) << what(yes);
    EXPECT_EQ(yes.out, "A1.01          0.000 V -> 2.000 V  verified\n");
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          2.000 V\n");
}

// DMA Profinet manual §6: E17 "Set value activation mode"; 0xB0 "Enable active", "Bus Disable
// Card" — the set-value source and the control word move the valve as well as a set value.
TEST_F(CliConfirm, TheSetValueSourceAndTheControlWordNeedYesToo)
{
    for (const char *assignment : {"E17=2", "0xB0=32768"}) {
        const CliRun r = cli(QStringList{"set", QString::fromLatin1(assignment)} + m_sim);
        EXPECT_EQ(r.code, kExitUsage) << assignment << '\n' << what(r);
        EXPECT_TRUE(r.complains("pass --yes")) << r.err;
    }
    EXPECT_EQ(get("E17", m_sim).find("E17"), 0u);
    EXPECT_EQ(cli(QStringList{"--json", "get", "E17"} + m_sim).json()["values"][0]["raw"], 0);
}

TEST_F(CliConfirm, ASettingNeedsNoConfirmation)
{
    const CliRun set = cli(QStringList{"set", "C1.07=1.000"} + m_sim);
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_EQ(set.out, "C1.07          0.000 V -> 1.000 V  verified\n");
    EXPECT_TRUE(set.err.empty()) << set.err;
}

// Nothing moves when the device already holds the value: the write skips it, so nobody is asked.
TEST_F(CliConfirm, AnUnchangedSetValueAsksNothing)
{
    const CliRun same = cli(QStringList{"set", "A1.01=0.000"} + m_sim);
    ASSERT_EQ(same.code, kExitOk) << what(same);
    EXPECT_EQ(same.out, "A1.01          0.000 V -> 0.000 V  unchanged\n");
}

TEST_F(CliConfirm, OnATerminalThePersonDecides)
{
    const CliRun no = cliOnTerminal(QStringList{"set", "A1.01=1.500"} + m_sim, "n\n");
    EXPECT_EQ(no.code, kExitUsage) << what(no);
    EXPECT_TRUE(no.complains("This write can move the actuator:\n"
                             "  module 1: dma-pn-v51 V51.00, mode 3: A1.01 0.000 V -> 1.500 V\n"
                             "Write it? [y/N] "))
        << no.err;
    EXPECT_TRUE(no.complains("not confirmed; nothing was sent")) << no.err;
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          0.000 V\n");

    // End of input is no answer, so no.
    EXPECT_EQ(cliOnTerminal(QStringList{"set", "A1.01=1.500"} + m_sim, "").code, kExitUsage);
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          0.000 V\n");

    const CliRun yes = cliOnTerminal(QStringList{"set", "A1.01=1.500"} + m_sim, "y\n");
    ASSERT_EQ(yes.code, kExitOk) << what(yes);
    EXPECT_EQ(yes.out, "A1.01          0.000 V -> 1.500 V  verified\n");
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          1.500 V\n");

    // --yes asks nothing even on a terminal.
    const CliRun scripted = cliOnTerminal(QStringList{"set", "--yes", "A1.01=0.000"} + m_sim, "");
    ASSERT_EQ(scripted.code, kExitOk) << what(scripted);
    EXPECT_TRUE(scripted.err.empty()) << scripted.err;
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          0.000 V\n");
}

// An old file that saved A1.01 writes its settings and lists A1.01 as ignored.
TEST_F(CliConfirm, WriteNeverWritesAFilesProcessValues)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = writeFile("old.vtpar", R"({"format": "valvetune-parameters",
        "formatVersion": 1, "modules": [{"address": 1, "family": "dma-pn-v51", "values": [
            {"name": "A1.01", "id": 31, "raw": 2000},
            {"name": "d1.11", "id": 11, "raw": 1234},
            {"name": "C1.07", "id": 48, "raw": 500}]}]})");
    const CliRun write = cli(QStringList{"--json", "write", file} + m_sim);
    ASSERT_EQ(write.code, kExitOk) << what(write);
    EXPECT_TRUE(write.complains("process values, not settings, kept in the file and ignored for "
                                "writing: A1.01"))
        << write.err;
    EXPECT_TRUE(write.complains("live values, not settings, kept in the file and ignored for "
                                "writing: d1.11"))
        << write.err;
    const auto module = write.json()["modules"][0];
    ASSERT_EQ(module["changes"].size(), 1u) << write.out;
    EXPECT_EQ(module["changes"][0]["name"], "C1.07");
    EXPECT_EQ(
        module["skipped"][0],
        (nlohmann::json{{"name", "A1.01"}, {"status", "not-a-setting"}, {"reason", "process"}}));
    EXPECT_EQ(get("A1.01", m_sim), "A1.01          0.000 V\n");
    EXPECT_EQ(get("C1.07", m_sim), "C1.07          0.500 V\n");

    // Nor are they compared.
    const CliRun diff = cli(QStringList{"diff", file} + m_sim);
    ASSERT_EQ(diff.code, kExitOk) << what(diff);
    EXPECT_TRUE(diff.says(": no differences (")) << diff.out;
}

// A file that changes E17 (a setting that moves the valve): the gate asks before anything of the
// file is written.
TEST_F(CliConfirm, WriteOfTheSetValueSourceNeedsYes)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = writeFile("e17.vtpar", R"({"format": "valvetune-parameters",
        "formatVersion": 1, "modules": [{"address": 1, "family": "dma-pn-v51", "values": [
            {"name": "C1.07", "id": 48, "raw": 500},
            {"name": "E17", "id": 112, "raw": 2}]}]})");
    const CliRun refused = cli(QStringList{"write", file} + m_sim);
    EXPECT_EQ(refused.code, kExitUsage) << what(refused);
    EXPECT_TRUE(refused.complains("module 1: dma-pn-v51 V51.00, mode 3: E17 ")) << refused.err;
    EXPECT_TRUE(refused.complains("pass --yes")) << refused.err;
    EXPECT_EQ(get("C1.07", m_sim), "C1.07          0.000 V\n");

    // A dry run writes nothing and asks nothing.
    EXPECT_EQ(cli(QStringList{"write", "--dry-run", file} + m_sim).code, kExitOk);

    const CliRun yes = cli(QStringList{"--json", "write", "--yes", file} + m_sim);
    ASSERT_EQ(yes.code, kExitOk) << what(yes);
    EXPECT_EQ(yes.json()["modules"][0]["changes"].size(), 2u) << yes.out;
    EXPECT_EQ(cli(QStringList{"--json", "get", "E17"} + m_sim).json()["values"][0]["raw"], 2);
}

TEST_F(CliConfirm, ReadOutSavesSettingsOnly)
{
    ASSERT_TRUE(m_dir.isValid());
    const QString file = m_dir.filePath(QStringLiteral("read.vtpar"));
    const CliRun read = cli(QStringList{"read", "--out", file} + m_sim);
    ASSERT_EQ(read.code, kExitOk) << what(read);
    QFile saved(file);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    const QByteArray text = saved.readAll();
    EXPECT_TRUE(text.contains("{\"name\": \"C1.07\", "));
    EXPECT_TRUE(text.contains("{\"name\": \"E17\", "));    // a setting, though valve-moving
    EXPECT_TRUE(text.contains("{\"name\": \"S1.01\", "));  // an internal set value, stored
    EXPECT_FALSE(text.contains("{\"name\": \"A1.01\", ")); // process values
    EXPECT_FALSE(text.contains("{\"name\": \"0xB0\", "));
    EXPECT_FALSE(text.contains("{\"name\": \"d1.11\", ")); // live values
    EXPECT_FALSE(text.contains("{\"name\": \"So.in\", "));
}

TEST_F(CliConfirm, HelpNamesTheOption)
{
    for (const char *command : {"set", "write"}) {
        const CliRun help = cli({command, "--help"});
        ASSERT_EQ(help.code, kExitOk);
        EXPECT_TRUE(help.says("[--yes]")) << help.out;
        EXPECT_TRUE(help.says("  --yes  ")) << help.out;
    }
}

} // namespace
} // namespace vt::clitest
