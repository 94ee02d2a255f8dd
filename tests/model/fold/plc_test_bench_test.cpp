// The PLC test bench against the simulator's node image (issue #9 step 8): cyclic CMD 15 with a
// new TADR every telegram, each module's multiplexed answer decoded and filed under its SADR
// (DMA Profinet manual §4.2 / §4.4.2: E22 = 1, 2, 3, then 1 again; OPAT manual §3.2).
#include "dict/dictionary_loader.h"
#include "model/fold/plc_test_bench.h"
#include "model/session/connection.h"

#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>
#include <set>

namespace vt::model {
namespace {

constexpr int kWaitMs = 30'000;

std::unique_ptr<Connection> openSim(const std::string &family, std::size_t modules,
                                    const std::string &protocol)
{
    ConnectionSpec spec;
    spec.kind = ConnectionKind::Sim;
    spec.sim.family = family;
    spec.sim.modules = modules;
    spec.sim.protocol = dev::fromKey<dev::LinkProtocol>(protocol);
    auto made = Connection::create(spec, *dev::builtinDictionaries());
    if (!made.ok()) {
        ADD_FAILURE() << made.error().toStdString();
        return nullptr;
    }
    std::unique_ptr<Connection> connection = std::move(made).value();
    connection->open();
    if (!QTest::qWaitFor([&] { return connection->isOpen(); }, kWaitMs)) {
        ADD_FAILURE() << "the simulator link did not open";
        return nullptr;
    }
    return connection;
}

bool everyModuleAnswered(const PlcTestBench &bench, quint64 times)
{
    for (const BenchModule &m : bench.modules())
        if (m.answers < times)
            return false;
    return true;
}

TEST(PlcTestBench, DecodesEveryModulesAnswerWithTadrToggling)
{
    auto c = openSim("dma-pn-v51", 3, "node-image");
    ASSERT_TRUE(c);
    ASSERT_TRUE(PlcTestBench::supports(c->session()));
    PlcTestBench bench(c->session(), dev::hcs::Family::Dma, 3);
    bench.setIntervalMs(5);
    std::vector<std::uint8_t> order;
    QObject::connect(&bench, &PlcTestBench::moduleAnswered, &bench, [&](int index) {
        order.push_back(bench.modules()[static_cast<std::size_t>(index)].address);
    });
    for (std::size_t i = 0; i < 3; ++i)
        bench.setSetpoints(i, {0, static_cast<std::int16_t>(1000 * (i + 1)), 0});
    bench.start();
    EXPECT_TRUE(QTest::qWaitFor([&] { return everyModuleAnswered(bench, 3); }, kWaitMs));
    bench.stop();

    const BenchCounters &counters = bench.counters();
    EXPECT_EQ(counters.exceptions, 0u);
    EXPECT_EQ(counters.failures, 0u);
    EXPECT_EQ(counters.stale, 0u);
    // One answer per telegram, module by module: 1, 2, 3, 1, 2, 3 …
    ASSERT_GE(order.size(), 9u);
    for (std::size_t i = 1; i < order.size(); ++i)
        EXPECT_EQ(order[i], order[i - 1] % 3 + 1) << "answer " << i;
    std::set<std::uint8_t> tadrs;
    std::size_t total = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const BenchModule &m = bench.modules()[i];
        EXPECT_EQ(m.address, i + 1);
        ASSERT_TRUE(m.last);
        EXPECT_EQ(m.last->sadr, i + 1);
        tadrs.insert(m.tadrs.begin(), m.tadrs.end());
        total += m.tadrs.size();
    }
    // Every answer came to a telegram of its own: no TADR answered twice.
    EXPECT_EQ(tadrs.size(), total);
    EXPECT_EQ(bench.lastRequest().size(),
              3u + 5u * 3u); // DMA Profinet manual §4.1: 18 bytes for 3 modules
}

TEST(PlcTestBench, OpatMasterAndSlaves)
{
    auto c = openSim("opat", 3, "node-image");
    ASSERT_TRUE(c);
    PlcTestBench bench(c->session(), dev::hcs::Family::Opat, 3);
    bench.setIntervalMs(5);
    bench.start();
    EXPECT_TRUE(QTest::qWaitFor([&] { return everyModuleAnswered(bench, 2); }, kWaitMs));
    bench.stop();
    EXPECT_EQ(bench.modules()[0].last->sadr, 0); // OPAT manual §3.2: the master answers as SADR 0
    EXPECT_EQ(bench.modules()[2].last->sadr, 2);
    EXPECT_EQ(bench.counters().exceptions, 0u);
}

// The node answers exception 7 when SNUM does not match its modules (OPAT manual §2.6).
TEST(PlcTestBench, WrongModuleCountGetsTheNodesException)
{
    auto c = openSim("dma-pn-v51", 3, "node-image");
    ASSERT_TRUE(c);
    PlcTestBench bench(c->session(), dev::hcs::Family::Dma, 2);
    QSignalSpy exception(&bench, &PlcTestBench::exceptionReceived);
    EXPECT_TRUE(bench.sendOnce());
    ASSERT_TRUE(exception.wait(kWaitMs));
    EXPECT_EQ(exception.front().front().toInt(), 7);
    EXPECT_FALSE(exception.front().at(1).toString().isEmpty());
}

TEST(PlcTestBench, RefusesWhatCmd15CannotCarry)
{
    EXPECT_FALSE(PlcTestBench::checkModules(dev::hcs::Family::Dma, 6).isEmpty());
    EXPECT_FALSE(PlcTestBench::checkModules(dev::hcs::Family::Opat, 9).isEmpty());
    EXPECT_TRUE(PlcTestBench::checkModules(dev::hcs::Family::Dma, 5).isEmpty());
    EXPECT_TRUE(PlcTestBench::checkModules(dev::hcs::Family::Opat, 8).isEmpty());

    auto c = openSim("dma-pn-v51", 3, "modbus-tcp");
    ASSERT_TRUE(c);
    EXPECT_FALSE(PlcTestBench::supports(c->session())); // CMD 15 needs the node image link
    PlcTestBench bench(c->session(), dev::hcs::Family::Dma, 3);
    QSignalSpy stopped(&bench, &PlcTestBench::stopped);
    bench.start();
    EXPECT_EQ(stopped.size(), 1);
    EXPECT_FALSE(bench.isRunning());
}

} // namespace
} // namespace vt::model
