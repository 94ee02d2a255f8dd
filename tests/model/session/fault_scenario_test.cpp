// Fault scenarios: 2 % dropped and 0.5 % corrupted frames — read all still completes
// with the right values, over several seeds; no out-of-range value is ever sent.
#include "modbus/rtu.h"
#include "model/session/write_job.h"
#include "sim_rig.h"

#include <QSignalSpy>

namespace vt::test {
namespace {

TEST(FaultScenario, ReadAllCompletesWithCorrectValuesUnderDropsAndCorruption)
{
    for (std::uint32_t seed : {1u, 7u, 42u}) {
        link::FaultSpec faults;
        faults.tx.drop = faults.rx.drop = 0.02;
        faults.tx.corrupt = faults.rx.corrupt = 0.005;
        faults.seed = seed;
        model::SessionOptions options;
        options.turnaround = std::chrono::milliseconds(40);
        options.retries = 5;
        auto c = openSim({"dma-pb-v32", 1, {}, faults, options});
        ASSERT_TRUE(c);
        const auto rows = model::readableRows(c->dictionary(), c->simModule().version(),
                                              std::to_string(c->simModule().mode()));
        for (int round = 0; round < 3; ++round) {
            std::optional<model::ReadResult> result;
            c->access().read(c->address(), rows, model::Priority::User,
                             [&](const model::ReadResult &r) { result = r; });
            ASSERT_TRUE(waitFor(result, 60'000));
            ASSERT_TRUE(result->complete())
                << "seed " << seed << ": " << result->failures.front().outcome.reason.toStdString();
            for (const model::RowValue &v : result->values) {
                if (v.row->block != "d") {
                    EXPECT_EQ(dev::rawNumber(v.value), storedRaw(c->simModule(), *v.row))
                        << v.row->name;
                }
            }
        }
        const auto &counters = c->faultLink()->counters();
        EXPECT_GT(counters.txDropped + counters.rxDropped + counters.txCorrupted +
                      counters.rxCorrupted,
                  0u)
            << "seed " << seed << ": the schedule injected nothing, the test proves nothing";
    }
}

TEST(FaultScenario, NoOutOfRangeValueIsEverSent)
{
    link::FaultSpec faults;
    faults.rx.drop = 0.02;
    auto c = openSim({"dma-pn-v51", 1, {}, faults, {}});
    ASSERT_TRUE(c);
    std::vector<QByteArray> writes;
    QObject::connect(&c->session(), &model::Session::frameSent,
                     [&](const QByteArray &bytes, int, qint64) {
                         if (bytes.size() > 1 && bytes[1] == 6)
                             writes.push_back(bytes);
                     });
    std::vector<model::WriteItem> list;
    for (const dev::ParamMeta &row : c->dictionary().params) {
        if (!row.writable() || !row.id || row.block != "C" || row.branch != 1)
            continue;
        for (double raw : {row.min - 1, row.max + 1, row.min}) {
            model::WriteItem item;
            item.row = &row;
            item.value = raw;
            list.push_back(item);
        }
    }
    ASSERT_GT(list.size(), 30u);
    model::WriteJob job(c->access(), c->address(), c->dictionary(), list,
                        model::AuditOrigin::Editor);
    QSignalSpy finished(&job, &model::WriteJob::finished);
    job.start();
    ASSERT_TRUE(finished.wait(120'000));
    for (const QByteArray &frame : writes) {
        auto decoded = dev::modbus::decodeRtuRequest(
            std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(frame.constData()),
                                          static_cast<std::size_t>(frame.size())));
        ASSERT_TRUE(decoded.ok());
        const auto &write = std::get<dev::modbus::WriteRequest>(decoded->pdu);
        const dev::ParamMeta *row = c->dictionary().findId(write.address);
        ASSERT_TRUE(row);
        const double raw = static_cast<double>(static_cast<std::int16_t>(write.value));
        EXPECT_GE(raw, row->min) << row->name;
        EXPECT_LE(raw, row->max) << row->name;
    }
    EXPECT_FALSE(writes.empty());
}

} // namespace
} // namespace vt::test
