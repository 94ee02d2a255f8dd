// Dsp408Adapter against the simulated ED1 (devices/sim/dsp408_device.h) behind its raw PROFIBUS
// image (Dsp408Server) and behind a PROFIBUS-master gateway's Modbus TCP registers
// (Dsp408GatewayServer): identification by db_Capability (ED1/SD1 manual §4.8.7), reads and
// writes by IND/PNU with the §4.6 response identifiers and error numbers, PZD control word and
// set value (§4.5.2), and the PKW handshake when answers are dropped, late, or older.
#include "access/dsp408_adapter.h"
#include "dict/dictionary_loader.h"
#include "dsp408/pkw.h"
#include "sim/dsp408_device.h"
#include "sim/dsp408_gateway_server.h"
#include "sim/dsp408_server.h"

#include <deque>
#include <functional>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::access;

namespace {

const Dictionary &ed1()
{
    return *builtinDictionaries()->find("wandfluh-ed1");
}

const ParamMeta &row(const char *name)
{
    const ParamMeta *r = ed1().find(name);
    EXPECT_TRUE(r) << name;
    return *r;
}

// The ED1's cyclic data exchange with a PKW answer that appears `lag` cycles late, as a slave
// that needs some bus cycles per parameter request does: until then the input image keeps the
// previous answer (§4.6.1: "On each request from the Master, the slave will send a response").
class LaggingImage : public ByteServer
{
public:
    LaggingImage(sim::Dsp408Device &device, std::size_t lag) : m_device(device), m_lag(lag) {}

    void receive(std::span<const std::uint8_t> bytes) override
    {
        auto request = dsp408::decodeRequestTelegram(bytes);
        ASSERT_TRUE(request.ok());
        auto response = m_device.exchange(*request);
        m_pending.push_back(*response.pkw);
        if (m_pending.size() > m_lag) {
            m_shown = m_pending.front();
            m_pending.pop_front();
        }
        response.pkw = m_shown;
        auto image = dsp408::encodeTelegram(response);
        m_out.insert(m_out.end(), image->begin(), image->end());
    }
    std::vector<std::uint8_t> drain() override { return std::exchange(m_out, {}); }

private:
    sim::Dsp408Device &m_device;
    std::size_t m_lag;
    std::deque<dsp408::Pkw> m_pending;
    dsp408::Pkw m_shown;
    Bytes m_out;
};

// The session's loop for one transaction: send, feed the answer, send what Progress asks for;
// no answer within `maxExchanges` frames is the session's timeout (resetFraming, next attempt).
// `wire` carries a request to the device and returns its answer (a test may drop or hold it).
struct Handshake
{
    ProtocolAdapter &adapter;
    std::function<Bytes(const Bytes &)> wire;
    int maxExchanges = 40;
    int exchanges = 0; // frames sent, over every attempt

    std::optional<Reply> run(const Transaction &t, int attempts = 4)
    {
        for (int attempt = 0; attempt < attempts; ++attempt) {
            Bytes request = adapter.encode(t);
            if (request.empty()) {
                ADD_FAILURE() << "encode() gave no bytes";
                return std::nullopt;
            }
            for (int i = 0; i < maxExchanges && !request.empty(); ++i) {
                ++exchanges;
                const Bytes answer = wire(request);
                request.clear();
                if (answer.empty())
                    break; // lost: wait for the timeout
                auto reply = adapter.feed(answer, t);
                if (!reply || reply->status == ReplyStatus::Mismatch)
                    break;
                if (reply->status != ReplyStatus::Progress)
                    return reply;
                request = reply->next;
            }
            adapter.resetFraming();
        }
        return std::nullopt;
    }
};

Bytes roundTrip(ByteServer &server, const Bytes &request)
{
    server.receive(request);
    return server.drain();
}

double stored(const sim::Dsp408Device &device, const ParamMeta &r)
{
    double value = 0;
    EXPECT_FALSE(device.read(r, value).has_value()) << r.name;
    return value;
}

struct ImageRig
{
    sim::Dsp408Device device{ed1()};
    sim::Dsp408Server server{device};
    Dsp408Adapter adapter{LinkProtocol::Dsp408Image};
    Handshake handshake{adapter, [this](const Bytes &b) { return roundTrip(server, b); }};
};

struct GatewayRig
{
    explicit GatewayRig(Dsp408LinkOptions o = {}, std::uint8_t gatewayUnit = 3)
        : options(o), unit(gatewayUnit), image(device, o.layout, o.gateway, gatewayUnit),
          server(image), adapter(LinkProtocol::Dsp408Gateway, o)
    {
    }
    Dsp408LinkOptions options;
    std::uint8_t unit;
    sim::Dsp408Device device{ed1()};
    sim::Dsp408GatewayImage image;
    sim::Dsp408GatewayServer server;
    Dsp408Adapter adapter;
    Handshake handshake{adapter, [this](const Bytes &b) { return roundTrip(server, b); }};
};

Transaction readOf(const ParamMeta &r, int module = 1)
{
    return Transaction::read(module, {&r});
}

void expectOk(const std::optional<Reply> &reply)
{
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::Ok) << reply->exceptionText.en;
}

// Every readable row, read one by one, equals what the device holds.
void expectReadAll(ProtocolAdapter &adapter, Handshake &handshake, const sim::Dsp408Device &device,
                   int module)
{
    std::vector<const ParamMeta *> rows;
    for (const ParamMeta &r : ed1().params)
        rows.push_back(&r);
    const auto plan = adapter.planRead(module, rows);
    ASSERT_GT(plan.size(), 40u);
    for (const Transaction &t : plan) {
        const auto reply = handshake.run(t);
        ASSERT_TRUE(reply) << t.rows.front()->name;
        ASSERT_EQ(reply->status, ReplyStatus::Ok) << t.rows.front()->name;
        ASSERT_EQ(reply->values.size(), 1u);
        if (t.rows.front()->kind != RowKind::Live) {
            EXPECT_EQ(rawNumber(reply->values.front()), stored(device, *t.rows.front()))
                << t.rows.front()->name;
        }
    }
}

} // namespace

TEST(Dsp408Adapter, ImageIdentifiesByCapability)
{
    ImageRig r;
    const auto plan = r.adapter.planIdentify(1);
    ASSERT_EQ(plan.size(), 1u);
    const auto reply = r.handshake.run(plan.front());
    expectOk(reply);
    // §4.8.7: 0x00130000 = hydraulic drive, open loop movement and position control.
    EXPECT_EQ(reply->identity.capability, 0x00130000u);
}

TEST(Dsp408Adapter, ImageReadsEveryRowByIndPnu)
{
    ImageRig r;
    expectReadAll(r.adapter, r.handshake, r.device, 1);
}

TEST(Dsp408Adapter, GatewayReadsEveryRowByIndPnu)
{
    GatewayRig r;
    expectReadAll(r.adapter, r.handshake, r.device, r.unit);
}

TEST(Dsp408Adapter, GatewayWithInputRegistersSwappedBytesAndLowWordFirst)
{
    Dsp408LinkOptions o;
    o.gateway.outputRegister = 200;
    o.gateway.inputRegister = 7;
    o.gateway.inputFunction = dsp408::InputFunction::InputRegisters;
    o.gateway.byteOrder = dsp408::RegisterByteOrder::FirstByteLow;
    o.layout.pzdWordOrder = dsp408::WordOrder::LowWordFirst;
    o.layout.indPosition = dsp408::IndPosition::Byte3;
    GatewayRig r(o, 1);
    expectReadAll(r.adapter, r.handshake, r.device, r.unit);
    // PZD set value in two registers, low word first (§4.5.2 words 2..3).
    const ParamMeta &setpoint = row("dpc_SetpointVal");
    expectOk(r.handshake.run(Transaction::write(r.unit, setpoint, 700.0)));
    EXPECT_EQ(r.adapter.pzdOut().setpoint, 700);
    EXPECT_EQ(stored(r.device, setpoint), 700); // what the card took from its PZD
}

TEST(Dsp408Adapter, GatewayAnswersOnlyItsUnit)
{
    GatewayRig r;
    const auto reply = r.handshake.run(readOf(row("dpc_PropFact1"), r.unit + 1));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException); // 0x0B gateway target failed
    EXPECT_EQ(reply->exceptionCode, 0x0B);
}

TEST(Dsp408Adapter, WritesOfEveryWidthAreAnsweredAndRefusalsCarryTheManualsErrorNumber)
{
    ImageRig r;
    // uint8 (AK 10 → 11), uint16 (AK 2 → 1), uint32 (AK 3 → 2), ED1/SD1 manual §4.6.
    for (const auto &[name, value] :
         std::vector<std::pair<const char *, double>>{{"dpc_PropFact1", 31},
                                                      {"dpc_ramp_AccTimePosVal", 250},
                                                      {"dpc_integrator_TiVal", 40}}) {
        const auto reply = r.handshake.run(Transaction::write(1, row(name), value));
        expectOk(reply);
        EXPECT_EQ(stored(r.device, row(name)), value) << name;
        expectOk(r.handshake.run(readOf(row(name))));
    }
    // §4.6 error 2: "lower or upper value range limit overflow".
    const ParamMeta &window = row("dpc_window_ThresholdVal");
    const auto tooBig = r.handshake.run(Transaction::write(1, window, window.max + 4));
    ASSERT_TRUE(tooBig);
    EXPECT_EQ(tooBig->status, ReplyStatus::DeviceException);
    EXPECT_EQ(tooBig->exceptionCode, 2);
    EXPECT_EQ(tooBig->exceptionText, dsp408::pkwErrorText(2));
    // §4.6 error 0 "undefined PNU": a row the device does not have.
    ParamMeta ghost = row("dpc_PropFact1");
    ghost.pnu = 2000;
    const auto unknown = r.handshake.run(readOf(ghost));
    ASSERT_TRUE(unknown);
    EXPECT_EQ(unknown->status, ReplyStatus::DeviceException);
    EXPECT_EQ(unknown->exceptionCode, 0);
    EXPECT_EQ(unknown->exceptionText.de, dsp408::pkwErrorText(0).de);
}

TEST(Dsp408Adapter, ControlWordAndSetValueTravelInThePzdAndDriveTheStateMachine)
{
    for (LinkProtocol carrier : {LinkProtocol::Dsp408Image, LinkProtocol::Dsp408Gateway}) {
        SCOPED_TRACE(key(carrier));
        sim::SimClock clock;
        sim::Dsp408Device device{ed1()};
        clock.attach(device);
        clock.advance(100'000); // NOT_READY → INIT after the self test
        sim::Dsp408Server imageServer{device};
        sim::Dsp408GatewayImage gateway{device, {}, {}, 1};
        sim::Dsp408GatewayServer gatewayServer{gateway};
        ByteServer &server = carrier == LinkProtocol::Dsp408Image
                                 ? static_cast<ByteServer &>(imageServer)
                                 : static_cast<ByteServer &>(gatewayServer);
        Dsp408Adapter adapter{carrier};
        Handshake handshake{adapter, [&](const Bytes &b) { return roundTrip(server, b); }};
        EXPECT_EQ(device.state(), dsp408::State::Init);
        expectOk(handshake.run(Transaction::write(1, row("dpc_SetpointVal"), 1000.0)));
        // §4.8.2: D, H and M set → TR_2, TR_3, TR_4 → DEVICE_MODE_ACTIVE.
        expectOk(handshake.run(Transaction::write(1, row("db_ControlWord"), 7.0)));
        EXPECT_EQ(device.state(), dsp408::State::DeviceModeActive);
        EXPECT_EQ(adapter.pzdOut().controlWord, 7);
        const auto status = handshake.run(readOf(row("db_StatusWord")));
        expectOk(status);
        EXPECT_EQ(rawNumber(status->values.front()), device.statusWord());
        ASSERT_TRUE(adapter.pzdIn());
        EXPECT_EQ(adapter.pzdIn()->statusWord & 0x0F, 0x0F); // R M H D
        clock.advance(2'000'000);
        expectOk(handshake.run(readOf(row("dpc_ActualVal"))));
        EXPECT_NEAR(device.actualValue(), 1000, 2);
        expectOk(handshake.run(Transaction::write(1, row("db_ControlWord"), 0.0)));
        EXPECT_EQ(device.state(), dsp408::State::Init);
    }
}

TEST(Dsp408Adapter, DroppedAnswersAreRetriedAndNeverMisattributed)
{
    ImageRig r;
    int n = 0;
    r.handshake.wire = [&](const Bytes &b) {
        const Bytes answer = roundTrip(r.server, b);
        return ++n % 3 == 0 ? Bytes{} : answer; // every third answer is lost
    };
    expectReadAll(r.adapter, r.handshake, r.device, 1);
}

TEST(Dsp408Adapter, LateAnswersAreNeverTakenForTheNextRequest)
{
    for (std::size_t lag : {1u, 2u, 5u}) {
        SCOPED_TRACE(lag);
        sim::Dsp408Device device{ed1()};
        LaggingImage server{device, lag};
        Dsp408Adapter adapter{LinkProtocol::Dsp408Image};
        Handshake handshake{adapter, [&](const Bytes &b) { return roundTrip(server, b); }};
        expectReadAll(adapter, handshake, device, 1);
    }
}

TEST(Dsp408Adapter, AnOlderAnswerOfTheSameParameterIsNotTheNewOne)
{
    // A write of P1 answered with 31, then the value changes on the card (PASO, the local
    // side); a read of P1 while the slave still shows the write's answer for 3 cycles must
    // return the new value, not the 31 of the older exchange.
    sim::Dsp408Device device{ed1()};
    LaggingImage server{device, 3};
    Dsp408Adapter adapter{LinkProtocol::Dsp408Image};
    Handshake handshake{adapter, [&](const Bytes &b) { return roundTrip(server, b); }};
    const ParamMeta &p1 = row("dpc_PropFact1");
    const auto written = handshake.run(Transaction::write(1, p1, 31.0));
    expectOk(written);
    EXPECT_EQ(rawNumber(written->values.front()), 31);
    ASSERT_FALSE(device.write(p1, 44).has_value());
    const auto read = handshake.run(readOf(p1));
    expectOk(read);
    EXPECT_EQ(rawNumber(read->values.front()), 44);
}

TEST(Dsp408Adapter, GatewayIgnoresAnswersToEarlierModbusTransactions)
{
    GatewayRig r;
    Bytes held;
    int n = 0;
    r.handshake.wire = [&](const Bytes &b) {
        Bytes answer = roundTrip(r.server, b);
        if (++n == 3) { // hold one answer back and deliver it with a later one
            held = answer;
            return Bytes{};
        }
        if (!held.empty()) {
            answer.insert(answer.begin(), held.begin(), held.end());
            held.clear();
        }
        return answer;
    };
    expectReadAll(r.adapter, r.handshake, r.device, r.unit);
}
