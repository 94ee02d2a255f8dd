// The simulated module's state: EEPROM write time on the sim clock (DMA Profinet manual
// §3.4.1: "up to 25ms per parameter … cycle time … greater than 30ms"), power cycle, hardware
// enable / bus disable, the module state word (ID 0xB0), error states with their numbers
// (DMA Profinet manual §4.5.1.1, OPAT manual §7 ERR), and the module's CMD 15 share.
#include "hcs/status_bits.h"
#include "hcs_sim_support.h"
#include "sim/hcs_codes.h"

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

std::uint16_t idOf(const HcsModule &m, const char *name)
{
    const ParamMeta *row = m.storage().find(name);
    EXPECT_TRUE(row) << name;
    return row ? static_cast<std::uint16_t>(*row->id) : 0;
}

} // namespace

TEST(HcsSimModule, EepromWriteTakes25msAndRefusesASecondWriteMeanwhile)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v51", "51", 3}));
    const std::uint16_t c107 = idOf(m, "C1.07"), c108 = idOf(m, "C1.08"), a101 = idOf(m, "A1.01");
    ASSERT_EQ(m.storage().meta(c107)->persistence, Persistence::Eeprom);
    ASSERT_EQ(m.storage().meta(a101)->persistence, Persistence::Volatile);

    ASSERT_TRUE(m.write(c107, 1000).ok()); // DMA Profinet manual §3.7: C1.07 = 1.000 V
    EXPECT_TRUE(m.eepromBusy());
    EXPECT_EQ(m.storage().raw(c107), 1000);    // the card works with it at once …
    EXPECT_EQ(m.storage().committed(c107), 0); // … the EEPROM has it 25 ms later
    EXPECT_EQ(m.write(c108, 500).exception, exce::kWriteFailed);
    EXPECT_EQ(m.storage().raw(c108), 0);
    EXPECT_TRUE(m.write(a101, 1000).ok()) << "a volatile row needs no EEPROM time";

    clock.advance(24'500);
    EXPECT_EQ(m.write(c108, 500).exception, exce::kWriteFailed);
    clock.advance(500);
    EXPECT_FALSE(m.eepromBusy());
    EXPECT_EQ(m.storage().committed(c107), 1000);
    EXPECT_TRUE(m.write(c108, 500).ok());

    // The session's pacing (≥ 30 ms, ARCHITECTURE.md "Edit") never meets a refusal.
    for (int i = 0; i < 5; ++i) {
        clock.advance(30'000);
        EXPECT_TRUE(m.write(c107, static_cast<std::uint16_t>(100 * i)).ok()) << i;
    }
}

TEST(HcsSimModule, EepromDelayPolicyAnswersWhenTheEepromIsFree)
{
    SimClock clock;
    HcsModuleConfig c = configFor({"dma-pn-v51", "51", 3});
    c.eepromBusy = EepromBusyPolicy::Delay;
    HcsModule m(clock, c);
    const std::uint16_t c107 = idOf(m, "C1.07"), c108 = idOf(m, "C1.08");
    clock.advance(1000);
    EXPECT_EQ(m.write(c107, 1000).readyAtUs, 1000);
    EXPECT_EQ(m.write(c108, 500).readyAtUs, 26'000);
    EXPECT_EQ(m.write(c107, 2000).readyAtUs, 51'000);
    EXPECT_EQ(m.eepromFreeAtUs(), 76'000);
}

TEST(HcsSimModule, PowerCycleKeepsCommittedEepromRowsOnly)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v13", "13", 1}));
    const std::uint16_t c107 = idOf(m, "C1.07"), c108 = idOf(m, "C1.08"), a101 = idOf(m, "A1.01");
    ASSERT_TRUE(m.write(c107, 1000).ok());
    clock.advance(25'000);
    ASSERT_TRUE(m.write(a101, 2000).ok());
    ASSERT_TRUE(m.write(c108, 700).ok());
    m.setPowered(false); // within C1.08's EEPROM time: lost
    m.setPowered(true);
    EXPECT_EQ(m.storage().raw(c107), 1000);
    EXPECT_EQ(m.storage().raw(c108), 0);
    EXPECT_EQ(m.storage().raw(a101), 0);
    EXPECT_EQ(m.read(0, 1).values.at(0), 1300) << "Vers survives";
    EXPECT_EQ(m.storage().get("E00"), 1);
}

TEST(HcsSimModule, StatusWordFollowsHardwareEnableAndBusDisable)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v51", "51", 3}));
    const std::uint16_t b0 = idOf(m, "0xB0");
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable);
    m.setBusDisable(true);
    EXPECT_EQ(m.read(b0, 1).values.at(0), hcs::kStatusHwEnable | hcs::kStatusBusDisable);
    // "The special function byte will be set to internal 0x00 when the hardware enable is
    // inactive."
    m.setHardwareEnable(false);
    EXPECT_EQ(m.statusWord(), 0);
    EXPECT_FALSE(m.busDisable());
    EXPECT_EQ(m.applyCyclic({hcs::kControlBusDisable | hcs::kControlDin1, 0, 0}), exce::kNone);
    EXPECT_FALSE(m.busDisable()) << "control byte ignored without hardware enable";
    m.setHardwareEnable(true);
    // 0xB0 is writable for BUS_DISABLE (0x8000) and Din_1 (V51).
    ASSERT_TRUE(m.write(b0, 0x8001).ok());
    EXPECT_TRUE(m.busDisable());
    EXPECT_TRUE(m.din(1));
    EXPECT_EQ(m.statusWord(), 0x8401);
}

TEST(HcsSimModule, OutputsOffWhileBusDisabled)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v13", "13", 1}));
    ASSERT_EQ(m.applyCyclic({0x00, 1000, 0}), exce::kNone);
    clock.advance(100'000);
    const int on = m.storage().get("d1.07") + m.storage().get("d1.08");
    EXPECT_NEAR(on, 270, 3)
        << "1.000 V of 2.7 A (E1.03 default) = 0.270 A, as DMA Profinet manual §4.4.1";
    ASSERT_EQ(m.applyCyclic({hcs::kControlBusDisable, 1000, 0}), exce::kNone);
    clock.advance(100'000);
    EXPECT_EQ(m.storage().get("d1.07") + m.storage().get("d1.08"), 0);
    EXPECT_EQ(m.cyclicValues().status, hcs::kStatusHwEnable | hcs::kStatusBusDisable);
}

TEST(HcsSimModule, DmaErrorLatchesWithItsNumberUntilAcknowledged)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v13", "13", 1}));
    ASSERT_EQ(m.applyCyclic({0x00, 5000, 0}), exce::kNone);
    OpenLoopPlant *plant = m.openLoop(1);
    ASSERT_TRUE(plant);
    plant->setSolenoidFault(false, SolenoidFault::ShortCircuit);
    plant->setSolenoidFault(true, SolenoidFault::ShortCircuit);
    clock.advance(50'000);
    // DMA Profinet manual §4.5.1.1: 0x0C 0x03 "Excess current or short circuit (peak > 8 A)".
    EXPECT_EQ(m.statusWord(), 0x0C03);
    EXPECT_EQ(m.read(idOf(m, "0xB0"), 1).values.at(0), 0x0C03);
    plant->setSolenoidFault(false, SolenoidFault::None);
    plant->setSolenoidFault(true, SolenoidFault::None);
    clock.advance(100'000); // the short's current decays with the solenoid's time constant
    EXPECT_EQ(m.statusWord(), 0x0C03) << "latched until acknowledged";
    EXPECT_EQ(m.storage().get("d1.07") + m.storage().get("d1.08"), 0)
        << "outputs disabled in error";
    m.setBusDisable(true);
    m.setBusDisable(false); // "Setting and resetting of the Bits (0x80) BUS_DISABLE"
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable);
    clock.advance(100'000);
    EXPECT_NEAR(m.storage().get("d1.07") + m.storage().get("d1.08"), 1350, 5)
        << "5.000 V of 2.7 A again";
}

TEST(HcsSimModule, OpatErrorShowsInErrAndIsAcknowledgedByTheEnable)
{
    SimClock clock;
    HcsModule m(clock, configFor({"opat", "34", 3}));
    ASSERT_EQ(m.applyCyclic({0x00, 5000, 0}), exce::kNone);
    ClosedLoopPlant *plant = m.closedLoop(1);
    ASSERT_TRUE(plant);
    plant->setSolenoidFault(false, SolenoidFault::OpenCircuit);
    plant->setSolenoidFault(true, SolenoidFault::OpenCircuit);
    clock.advance(500'000);
    ASSERT_TRUE(m.tripped());
    // OPAT manual §7 ERR 8 "wire break at the output stages".
    EXPECT_EQ(m.storage().get("ERR"), 8);
    EXPECT_EQ(m.statusWord(), 0x0C08);
    plant->setSolenoidFault(false, SolenoidFault::None);
    plant->setSolenoidFault(true, SolenoidFault::None);
    clock.advance(1000);
    m.setHardwareEnable(false);
    m.setHardwareEnable(true); // "hardware enable … to Low and then back to High"
    EXPECT_EQ(m.storage().get("ERR"), 0);
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable);
}

TEST(HcsSimModule, CyclicShareSetsTheProfileRowsAndAnswersItsValues)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v51", "51", 3}));
    ASSERT_EQ(m.profile(), hcs::Profile::DmaV51Mode34);
    // DMA Profinet manual §4.5.3: VALUE1 = A1.01, VALUE2 = A1.02; answer d1.11, d1.10.
    ASSERT_EQ(m.applyCyclic({0x00, 3000, 1200}), exce::kNone);
    EXPECT_EQ(m.storage().get("A1.01"), 3000);
    EXPECT_EQ(m.storage().get("A1.02"), 1200);
    clock.advance(200'000);
    const CyclicValues v = m.cyclicValues();
    EXPECT_EQ(v.value1, m.storage().get("d1.11"));
    EXPECT_EQ(v.value2, m.storage().get("d1.10"));
    EXPECT_EQ(v.value2, 3000) << "no ramps by default: d1.10 = A1.01";
    EXPECT_EQ(m.applyCyclic({0x00, 10000, 0}), exce::kWrongData);
    EXPECT_EQ(m.storage().get("A1.01"), 3000) << "a refused telegram changes nothing";
}

TEST(HcsSimModule, DinEnablesTheRemoteLoopControllerAndShowsDout)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v51", "51", 3}));
    m.storage().set("C1.00", 2); // remote loop controller (closes the loop while Din_1 is set)
    ASSERT_EQ(m.applyCyclic({hcs::kControlDin1, 1000, 0}), exce::kNone);
    clock.advance(1000);
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable | hcs::kStatusDin1 | hcs::kStatusDout1);
    ASSERT_EQ(m.applyCyclic({0x00, 1000, 0}), exce::kNone);
    clock.advance(1000);
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable);
    // V51 does not use Din_2 (DMA Profinet manual §4.5.3): the bit is ignored.
    ASSERT_EQ(m.applyCyclic({hcs::kControlDin2, 1000, 0}), exce::kNone);
    EXPECT_FALSE(m.din(2));
}

TEST(HcsSimModule, OpenLoopStatusLowByteIsAlwaysZero)
{
    SimClock clock;
    HcsModule m(clock, configFor({"dma-pn-v13", "13", 1}));
    // DMA Profinet manual §4.5.2: V13 reserves Din_1 …; "Low byte … otherwise: always zero".
    ASSERT_EQ(m.applyCyclic({0x7F, 1000, 0}), exce::kNone);
    clock.advance(1000);
    EXPECT_EQ(m.statusWord(), hcs::kStatusHwEnable);
}
