// valvetune-cli against a real valvetune-sim process for every family of the manuals that the
// previous suites do not already walk end to end (dma-pn-v51: cli_serial_test, cli_node_test; the
// ED1 in both gateway mappings: cli_ed1_test): info identifies the family, read reads every
// readable row without a failure, set writes a ramp with read-back and get finds it, monitor
// samples the family's default channels (docs/DICTIONARY.md "Monitor defaults"). The HCS modules
// over Modbus TCP, the SD7 over HART on the simulator's pseudo-terminal.
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"
#include "dict/dictionary_loader.h"
#include "sim_process.h"

namespace vt::clitest {
namespace {

using cli::kExitOk;

struct FamilyRun
{
    const char *family;
    const char *unit;    // the module get/set address ("" = the link's default)
    const char *setting; // a ramp row of the family, written as "250"
};

void PrintTo(const FamilyRun &run, std::ostream *os)
{
    *os << run.family;
}

class CliFamilies : public CliDevice, public ::testing::WithParamInterface<FamilyRun>
{
protected:
    void SetUp() override
    {
        CliDevice::SetUp();
        m_where = m_sim.listening();
        ASSERT_FALSE(m_where.isEmpty()) << m_sim.stderrText().toStdString();
    }
    static bool hart() { return std::string(GetParam().family) == "wandfluh-sd7"; }
    QStringList link() const
    {
        QStringList out{hart() ? "--hart" : "--tcp", m_where};
        if (*GetParam().unit)
            out << "--unit" << GetParam().unit;
        return out;
    }

    simtest::Sim m_sim{QStringList{"--device", GetParam().family}
                       << (hart() ? QStringList{"--pty"} : QStringList{"--tcp", "127.0.0.1:0"})};
    QString m_where;
};

TEST_P(CliFamilies, InfoReadSetGetAndMonitorAgainstTheSimulatorProcess)
{
    const std::string family = GetParam().family;
    const CliRun info = cli(QStringList{"info"} + link());
    ASSERT_EQ(info.code, kExitOk) << what(info);
    EXPECT_TRUE(info.says(": " + family)) << info.out;

    const CliRun read = cli(QStringList{"--json", "read"} + link());
    ASSERT_EQ(read.code, kExitOk) << what(read);
    const auto modules = read.json()["modules"];
    ASSERT_FALSE(modules.empty());
    EXPECT_GT(modules[0]["count"].get<int>(), 20);
    EXPECT_TRUE(modules[0]["failures"].empty()) << modules[0]["failures"].dump();

    const std::string setting = GetParam().setting;
    const CliRun set = cli(QStringList{"set", QString::fromStdString(setting + "=250")} + link());
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_TRUE(set.says("-> 250 ms  verified\n")) << set.out;
    const CliRun get = cli(QStringList{"get", QString::fromStdString(setting)} + link());
    ASSERT_EQ(get.code, kExitOk) << what(get);
    EXPECT_TRUE(get.says(" 250 ms\n")) << get.out;

    const CliRun monitor =
        cli(QStringList{"--json", "monitor", "--rate", "10", "--duration", "0.5"} + link());
    ASSERT_EQ(monitor.code, kExitOk) << what(monitor);
    const auto doc = monitor.json();
    const dev::Dictionary *dictionary = dev::builtinDictionaries()->find(family);
    ASSERT_TRUE(dictionary);
    const std::string mode = doc["module"]["mode"].get<std::string>();
    EXPECT_EQ(doc["rows"].size(), dictionary->monitor.forMode(mode).channels.size()) << monitor.out;
    EXPECT_GE(doc["samples"].get<int>(), 2) << monitor.out;
}

INSTANTIATE_TEST_SUITE_P(EveryFamily, CliFamilies,
                         ::testing::Values(FamilyRun{"opat", "0", "r1.01"},
                                           FamilyRun{"dma-pn-v13", "", "r1.01"},
                                           FamilyRun{"dma-pb-v15", "", "r1.01"},
                                           FamilyRun{"dma-pb-v22", "", "r1.01"},
                                           FamilyRun{"dma-pb-v32", "", "r1.01"},
                                           FamilyRun{"wandfluh-sd7", "", "dcol_RampAUp"}),
                         [](const ::testing::TestParamInfo<FamilyRun> &param) {
                             std::string name = param.param.family;
                             for (char &c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

} // namespace
} // namespace vt::clitest
