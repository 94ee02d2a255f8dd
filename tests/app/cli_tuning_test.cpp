// valvetune-cli test (app/cli/cmd_test.cpp) against the built-in simulator: nothing moves
// without --yes or a terminal's yes, the range is checked before anything is sent, the set value
// and its source go back afterwards, and the JSON, text and CSV say what was measured.
#include "cli_device_fixture.h"

#include <QFile>
#include <QTemporaryDir>

namespace vt::clitest {
namespace {

class CliTuning : public CliDevice
{
protected:
    std::string get(const char *name)
    {
        return cli(QStringList{"get", QString::fromLatin1(name)} + m_sim).out;
    }
    const QStringList m_sim{"--sim", "dma-pn-v51"};
    const QStringList m_step{"test", "step", "--from", "3", "--to", "5", "--hold", "0.3"};
};

TEST_F(CliTuning, ATestWithoutATerminalNeedsYesAndSendsNothing)
{
    const CliRun r = cli(m_step + m_sim);
    EXPECT_EQ(r.code, cli::kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("step test")) << r.err;
    EXPECT_TRUE(r.complains("A1.01")) << r.err;
    EXPECT_TRUE(r.complains("pass --yes")) << r.err;
    EXPECT_TRUE(r.complains("nothing was sent")) << r.err;
    EXPECT_EQ(get("A1.01"), "A1.01          0.000 V\n");
}

TEST_F(CliTuning, AStepRunsSwitchesTheSourceForTheTestAndPutsEverythingBack)
{
    ASSERT_EQ(cli(QStringList{"set", "--yes", "E17=0"} + m_sim).code, cli::kExitOk);
    const std::string source = get("E17");
    const CliRun r = cli(QStringList{"--json"} + m_step + QStringList{"--yes"} + m_sim);
    ASSERT_EQ(r.code, cli::kExitOk) << what(r);
    const auto j = r.json();
    EXPECT_EQ(j["end"], "finished");
    EXPECT_EQ(j["restored"], true);
    EXPECT_EQ(j["set_value"], "A1.01");
    EXPECT_EQ(j["actual"], "d1.11");
    EXPECT_GT(j["update_hz"].get<double>(), 0);
    ASSERT_EQ(j["runs"].size(), 1u);
    const auto &step = j["runs"][0];
    EXPECT_EQ(step["direction"], "up");
    EXPECT_EQ(step["from"], 3.0);
    EXPECT_EQ(step["to"], 5.0);
    // Figures or the reason there are none (the factory simulator's d1.11 follows the bus).
    EXPECT_TRUE(step.contains("rise_time_s") || step.contains("problem")) << step.dump();
    EXPECT_EQ(get("A1.01"), "A1.01          0.000 V\n");
    EXPECT_EQ(get("E17"), source);
}

TEST_F(CliTuning, ASineReportsGainAndPhasePerFrequency)
{
    const CliRun r = cli(QStringList{"--json", "test", "sine", "--amplitude", "1", "--offset", "4",
                                     "--frequency", "2", "--cycles", "2", "--yes"} +
                         m_sim);
    ASSERT_EQ(r.code, cli::kExitOk) << what(r);
    const auto j = r.json();
    ASSERT_EQ(j["points"].size(), 1u);
    EXPECT_EQ(j["points"][0]["frequency_hz"], 2.0);
    EXPECT_TRUE(j["points"][0].contains("gain_db"));
    EXPECT_TRUE(j["points"][0].contains("phase_deg"));
    EXPECT_TRUE(j["points"][0]["valid"].is_boolean());
    EXPECT_TRUE(j.contains("f_3db_hz"));
    EXPECT_EQ(j["restored"], true);
}

TEST_F(CliTuning, ASignalOutsideTheSetValuesRangeIsRefusedBeforeAnythingIsSent)
{
    const std::string before = get("E17");
    const CliRun r = cli(QStringList{"test", "step", "--from", "3", "--to", "12", "--yes"} + m_sim);
    EXPECT_EQ(r.code, cli::kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("A1.01")) << r.err;
    EXPECT_TRUE(r.complains("nothing was sent")) << r.err;
    EXPECT_EQ(get("E17"), before);
    EXPECT_EQ(get("A1.01"), "A1.01          0.000 V\n");
}

TEST_F(CliTuning, OptionsAreCheckedAndNumbersFollowTheLanguage)
{
    EXPECT_EQ(cli(QStringList{"test", "step", "--to", "5", "--yes"} + m_sim).code, cli::kExitUsage);
    EXPECT_EQ(cli(QStringList{"test", "wobble", "--yes"} + m_sim).code, cli::kExitUsage);
    const CliRun english =
        cli(QStringList{"test", "step", "--from", "3,5", "--to", "5", "--yes"} + m_sim);
    EXPECT_EQ(english.code, cli::kExitUsage) << what(english);
    EXPECT_TRUE(english.complains("--from")) << english.err;
    const CliRun german = cli(QStringList{"--json", "test", "step", "--lang", "de", "--from", "3,5",
                                          "--to", "4,5", "--hold", "0,2", "--yes"} +
                              m_sim);
    ASSERT_EQ(german.code, cli::kExitOk) << what(german);
    EXPECT_EQ(german.json()["runs"][0]["from"], 3.5);
}

TEST_F(CliTuning, TheCsvHoldsTheWrittenSetValueAndTheChannels)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("step.csv"));
    const CliRun r = cli(m_step + QStringList{"--yes", "--csv", path} + m_sim);
    ASSERT_EQ(r.code, cli::kExitOk) << what(r);
    EXPECT_TRUE(r.says("restored: A1.01 back to 0.000 V")) << r.out;
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    ASSERT_GT(lines.size(), 5);
    EXPECT_TRUE(lines[0].startsWith("time_s,A1.01 written [V],d1.10 [V],d1.11 [V]"))
        << lines[0].toStdString();
    const QList<QByteArray> last = lines[lines.size() - 2].split(',');
    EXPECT_EQ(last[1], "5.000000");
}

} // namespace
} // namespace vt::clitest
