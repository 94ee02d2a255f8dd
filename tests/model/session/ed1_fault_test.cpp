// The Wandfluh ED1 over its PROFIBUS image (raw and behind a gateway's Modbus TCP registers) on
// the built-in simulator behind a FaultLink: frames dropped both ways and every answer held back,
// so attempts time out while the answers of earlier attempts and polls still arrive. The PKW
// handshake (ED1/SD1 manual §4.6: AK, PNU and IND of the answer; AK 0 before a repeated
// parameter) must still give every row its own value — never one of another parameter — and a
// write followed by a change on the card must read back the new value.
#include "dict/cooking.h"
#include "sim/dsp408_device.h"
#include "sim_rig.h"

namespace vt::test {
namespace {

class Ed1Faults : public ::testing::TestWithParam<const char *>
{
};

double stored(const dev::sim::Dsp408Device &device, const dev::ParamMeta &row)
{
    double value = 0;
    EXPECT_FALSE(device.read(row, value).has_value()) << row.name;
    return value;
}

TEST_P(Ed1Faults, ReadAllGivesEveryRowItsOwnValueUnderDropsAndLateAnswers)
{
    for (std::uint32_t seed : {1u, 5u}) {
        SCOPED_TRACE(seed);
        link::FaultSpec faults;
        faults.tx.drop = faults.rx.drop = 0.08;
        faults.rx.delayMs = 6;
        faults.seed = seed;
        model::SessionOptions options;
        options.turnaround = std::chrono::milliseconds(30);
        options.retries = 8;
        auto c = connectSim({"wandfluh-ed1", 1, GetParam(), faults, options});
        ASSERT_TRUE(c);
        dev::sim::Dsp408Device &device = *c->simEndpoint()->ed1();
        // Settings that differ from their neighbours', so a value given to the wrong row shows.
        int k = 0;
        for (const dev::ParamMeta &row : c->dictionary().params) {
            if (row.writable() && row.readable() && row.kind == dev::RowKind::Setting &&
                row.enums.empty() && row.max - row.min > 40)
                (void)device.write(row, row.min + 3 + (k++ % 30));
        }
        ASSERT_GT(k, 10);
        const auto rows = model::readableRows(c->dictionary(), "", "");
        std::optional<model::ReadResult> result;
        c->access().read(c->address(), rows, model::Priority::User,
                         [&](const model::ReadResult &r) { result = r; });
        ASSERT_TRUE(waitFor(result, 120'000));
        ASSERT_TRUE(result->complete()) << result->failures.front().outcome.reason.toStdString();
        for (const model::RowValue &v : result->values) {
            if (v.row->kind != dev::RowKind::Live) {
                EXPECT_EQ(dev::rawNumber(v.value), stored(device, *v.row)) << v.row->name;
            }
        }
        const auto &counters = c->faultLink()->counters();
        EXPECT_GT(counters.txDropped + counters.rxDropped, 0u) << "nothing was dropped";
        EXPECT_GT(c->session().counters().timeouts, 0u) << "no attempt timed out";
    }
}

TEST_P(Ed1Faults, AWriteThenAChangeOnTheCardReadsBackTheNewValue)
{
    link::FaultSpec faults;
    faults.rx.delayMs = 4;
    auto c = connectSim({"wandfluh-ed1", 1, GetParam(), faults, {}});
    ASSERT_TRUE(c);
    const dev::ParamMeta &p1 = c->row("dpc_PropFact1");
    std::optional<model::Outcome> written;
    c->access().write(c->address(), p1, 31.0, model::Priority::User, std::nullopt,
                      [&](const model::Outcome &o) { written = o; });
    ASSERT_TRUE(waitFor(written));
    ASSERT_EQ(written->status, model::OutcomeStatus::Ok) << written->reason.toStdString();
    ASSERT_FALSE(c->simEndpoint()->ed1()->write(p1, 44).has_value());
    EXPECT_EQ(c->read("dpc_PropFact1"), 44.0);
}

INSTANTIATE_TEST_SUITE_P(Mappings, Ed1Faults, ::testing::Values("dsp408-image", "dsp408-gateway"),
                         [](const auto &param) {
                             return std::string(param.param) == "dsp408-image"
                                        ? std::string("Image")
                                        : std::string("Gateway");
                         });

} // namespace
} // namespace vt::test
