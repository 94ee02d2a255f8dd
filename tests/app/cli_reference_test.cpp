// valvetune-cli reference (app/cli/cmd_reference.cpp) against the built-in simulator's
// commissioned position loop (C1.13 = 2.00): nothing moves without --yes or a terminal's yes; a
// reference saved, then compared after the P gain changed, lists C1.13 and a rise time beyond
// its limit (exit 1) with the set value back; a file of another family is refused before
// anything is sent.
#include "cli_device_fixture.h"
#include "model/tuning/reference_file.h"

#include <QFile>
#include <QTemporaryDir>

namespace vt::clitest {
namespace {

class CliReference : public CliDevice
{
protected:
    std::string get(const char *name)
    {
        return cli(QStringList{"get", QString::fromLatin1(name)} + m_sim).out;
    }
    QStringList save(const QString &path) const
    {
        return {"reference", "save",        "--out", path,     "--centre",
                "4",         "--amplitude", "1",     "--hold", "0.6"};
    }
    QTemporaryDir m_dir;
    const QString m_path = m_dir.filePath(QStringLiteral("axis.vtref"));
    const QStringList m_sim{"--sim", "dma-pn-v51"};
};

TEST_F(CliReference, WithoutATerminalItNeedsYesAndSendsNothing)
{
    const std::string before = get("A1.01");
    const CliRun r = cli(save(m_path) + m_sim);
    EXPECT_EQ(r.code, cli::kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("reference test set")) << r.err;
    EXPECT_TRUE(r.complains("pass --yes")) << r.err;
    EXPECT_TRUE(r.complains("nothing was sent")) << r.err;
    EXPECT_FALSE(QFile::exists(m_path));
    EXPECT_EQ(get("A1.01"), before);
}

TEST_F(CliReference, AChangedGainShowsAsASettingDifferenceAndARiseTimeBeyondItsLimit)
{
    const CliRun saved = cli(QStringList{"--json"} + save(m_path) + QStringList{"--yes"} + m_sim);
    ASSERT_EQ(saved.code, cli::kExitOk) << what(saved);
    ASSERT_TRUE(QFile::exists(m_path));
    EXPECT_GT(saved.json()["settings"].get<int>(), 20);
    EXPECT_EQ(saved.json()["tests"], 1);
    const std::string setValue = get("A1.01");

    ASSERT_EQ(cli(QStringList{"set", "--yes", "C1.13=1.00"} + m_sim).code, cli::kExitOk);
    const CliRun r = cli(QStringList{"--json", "reference", "compare", m_path, "--yes"} + m_sim);
    EXPECT_EQ(r.code, cli::kExitDeviceError) << what(r);
    EXPECT_TRUE(r.complains("drifted beyond its limit")) << r.err;
    const auto j = r.json();
    ASSERT_EQ(j["params"].size(), 1u) << j.dump();
    EXPECT_EQ(j["params"][0]["row"], "C1.13");
    EXPECT_EQ(j["params"][0]["reference"], 2.0);
    EXPECT_EQ(j["params"][0]["now"], 1.0);
    bool rise = false;
    for (const auto &m : j["metrics"])
        if (m["test"] == "step-up" && m["metric"] == "rise-time") {
            rise = true;
            EXPECT_GT(m["delta_pct"].get<double>(), 20) << m.dump();
            EXPECT_EQ(m["exceeded"], true);
        }
    EXPECT_TRUE(rise) << j.dump();
    EXPECT_EQ(j["exceeded"], true);
    EXPECT_EQ(get("A1.01"), setValue); // the set value is back
}

TEST_F(CliReference, AFileOfAnotherFamilyIsRefusedBeforeAnythingIsSent)
{
    model::ReferenceFileData file;
    file.family = "opat";
    file.mode = "3";
    file.setValue = "A1.01";
    file.address = 1;
    {
        QFile out(m_path);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(QByteArray::fromStdString(model::referenceJson(file)));
    }
    const CliRun r = cli(QStringList{"reference", "compare", m_path, "--yes"} + m_sim);
    EXPECT_EQ(r.code, cli::kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("does not fit")) << r.err;
    EXPECT_TRUE(r.complains("opat")) << r.err;
    EXPECT_TRUE(r.complains("nothing was sent")) << r.err;
}

} // namespace
} // namespace vt::clitest
