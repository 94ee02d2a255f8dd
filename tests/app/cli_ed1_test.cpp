// valvetune-cli against a real valvetune-sim process serving the Wandfluh ED1 over TCP, in both
// mappings of its PROFIBUS image (ARCHITECTURE.md "Wandfluh ED1/SD1 online"): the raw cyclic
// image (dsp408-image) and a PROFIBUS-master gateway's Modbus TCP registers (dsp408-gateway,
// here with unit 2, the output image at 50, the input image at 10 read with FC 4 and each
// register's bytes swapped — both sides configured alike). info identifies by db_Capability
// (ED1/SD1 manual §4.8.7), read / get / set go by IND/PNU (§4.6), monitor polls, the control
// word passes the valve-moving gate.
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"
#include "sim_process.h"

namespace vt::clitest {
namespace {

using cli::kExitOk;
using cli::kExitUsage;

struct Mapping
{
    const char *name;
    QStringList options; // the same words for valvetune-sim and valvetune-cli
};

class CliEd1 : public CliDevice, public ::testing::WithParamInterface<Mapping>
{
protected:
    void SetUp() override
    {
        CliDevice::SetUp();
        m_tcp = m_sim.listening();
        ASSERT_TRUE(m_tcp.startsWith("127.0.0.1:")) << m_sim.stderrText().toStdString();
    }
    CliRun ed1(QStringList args) const
    {
        return cli(args << "--tcp" << m_tcp << GetParam().options);
    }

    simtest::Sim m_sim{QStringList{"--device", "wandfluh-ed1", "--tcp", "127.0.0.1:0"}
                       << GetParam().options};
    QString m_tcp;
};

TEST_P(CliEd1, InfoIdentifiesTheEd1ByItsCapability)
{
    const CliRun r = ed1({"info"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    EXPECT_TRUE(r.says("wandfluh-ed1")) << r.out;
    EXPECT_TRUE(r.says("capability 0x00130000")) << r.out;
    EXPECT_TRUE(r.says(GetParam().name)) << r.out;
}

TEST_P(CliEd1, ReadShowsEveryParameterInDisplayUnits)
{
    const CliRun r = ed1({"read"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    // §4.4 defaults: P-factor 20, window 16 × FactReference = 1.563 mm, position control.
    EXPECT_TRUE(r.says("dpc_PropFact1")) << r.out;
    EXPECT_TRUE(r.says("Position control axis")) << r.out;
    EXPECT_TRUE(r.says("1.563 mm")) << r.out;
}

TEST_P(CliEd1, SetIsRangeCheckedWrittenAndReadBack)
{
    CliRun r = ed1({"set", "dpc_PropFact1=33", "dpc_ramp_AccTimePosVal=250"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    EXPECT_TRUE(r.says("verified")) << r.out;
    r = ed1({"--json", "get", "dpc_PropFact1", "dpc_ramp_AccTimePosVal"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    EXPECT_EQ(r.json()["values"][0]["raw"], 33);
    EXPECT_EQ(r.json()["values"][1]["raw"], 250);
    // dpc_PropFact1 is 0..255 (§4.8): refused before anything is sent.
    r = ed1({"set", "dpc_PropFact1=256"});
    EXPECT_EQ(r.code, kExitUsage) << what(r);
    EXPECT_EQ(ed1({"--json", "get", "dpc_PropFact1"}).json()["values"][0]["raw"], 33);
}

TEST_P(CliEd1, ControlWordAndSetValueAreValveMovingWritesThatDriveTheStateMachine)
{
    // Without a terminal and without --yes nothing is sent.
    CliRun r = ed1({"set", "db_ControlWord=7"});
    EXPECT_EQ(r.code, kExitUsage) << what(r);
    EXPECT_TRUE(r.complains("--yes")) << r.err;
    // §4.8.2 / §4.2.2: set value first, then D + H + M → DEVICE_MODE_ACTIVE (status R M H D).
    r = ed1({"set", "--yes", "dpc_SetpointVal=50", "db_ControlWord=7"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    r = ed1(
        {"--json", "monitor", "db_StatusWord", "dpc_ActualVal", "--rate", "20", "--duration", "1"});
    ASSERT_EQ(r.code, kExitOk) << what(r);
    const auto doc = r.json();
    ASSERT_GT(doc["samples"].get<int>(), 10);
    const auto &last = doc["data"].back();
    const int status = last["raw"][0].get<int>();
    if (std::string(GetParam().name) == "dsp408-gateway") {
        // The gateway keeps the PZD registers between connections: still ACTIVE, and the axis
        // has moved to the set value (50 mm = 512 × FactReference).
        EXPECT_EQ(status & 0x0F, 0x0F) << status;
        EXPECT_NEAR(last["display"][1].get<double>(), 50.0, 1.0);
    } else {
        // The raw image's master is this connection: its images carry control word 0 until it
        // writes one (docs/PROTOCOL-NOTES.md), so a new connection finds the card in INIT.
        EXPECT_EQ(status & 0x0F, 0x08) << status;
    }
}

INSTANTIATE_TEST_SUITE_P(Mappings, CliEd1,
                         ::testing::Values(Mapping{"dsp408-image", {"--protocol", "dsp408-image"}},
                                           Mapping{"dsp408-gateway",
                                                   {"--protocol", "dsp408-gateway", "--unit", "2",
                                                    "--out-register", "50", "--in-register", "10",
                                                    "--in-function", "4", "--register-bytes",
                                                    "low-first"}}),
                         [](const auto &param) {
                             return std::string(param.param.name) == "dsp408-image"
                                        ? std::string("Image")
                                        : std::string("Gateway");
                         });

} // namespace
} // namespace vt::clitest
