// HcsModule: one simulated HCS module (OPAT master / CAN slave, DMA-2) of a dictionary family:
// its parameter image with the access rules the node answers with, version and mode, EEPROM
// persistence with the write time of the DMA Profinet manual §3.4.1, hardware enable and bus
// disable, the error states and the module state word (ID 0xB0 "internal digital switches"),
// its CMD 15 share (control byte and VALUE1/VALUE2 per hcs/profiles.h), and the plant behind it
// (OpenLoopPlant / ClosedLoopPlant per mode) stepping on the SimClock. docs/SIMULATOR.md.
// Owner: an HcsNode (or a test); single-threaded, on the thread that drives the clock.
#pragma once

#include "hcs/cmd15.h"
#include "hcs/profiles.h"
#include "hcs/types.h"
#include "sim/closed_loop_plant.h"
#include "sim/hcs_storage.h"
#include "sim/open_loop_plant.h"
#include "sim/sim_clock.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vt::dev::sim {

// DMA Profinet manual §3.4.1: "storage to the internal EEPROM of the device needs up to 25ms per
// parameter. So the cycle time of writing new parameter to a slave should be greater than 30ms."
// The manual does not say what a module does with a write that comes sooner; both readings are
// offered, refusing is the default because it makes a master without pacing visible.
enum class EepromBusyPolicy {
    Refuse, // exception 4 "writing of ID failed"; the value is not taken
    Delay,  // the write waits until the EEPROM is free; its answer comes then
};

struct HcsModuleConfig
{
    const Dictionary *dictionary = nullptr; // must outlive the module
    std::string version;        // major version as the dictionary lists it ("34"); empty: the first
    int versionRaw = 0;         // Vers (ID 0) = version × 100 (3403 = V34.03); 0: major × 100
    int mode = 0;               // E00; 0: the family's first mode
    std::uint8_t address = 1;   // OPAT: 0 master, 1..7 DIP switch; DMA: E22 (1..32)
    bool hardwareEnable = true; // the manuals' examples have the enable wired
    std::int64_t eepromWriteUs = 25'000;
    EepromBusyPolicy eepromBusy = EepromBusyPolicy::Refuse;
    // A CMD 3 / FC 3 block that covers an ID the module does not have: exception 2 (true), or
    // that ID reads 0 (false). The manuals do not say; real Modbus devices refuse the block.
    bool strictBlockReads = true;
};

struct ReadOutcome
{
    std::vector<std::uint16_t> values;
    std::uint8_t exception = 0; // 0: ok; else EXCE (sim/hcs_codes.h)
    bool ok() const { return exception == 0; }
};

struct WriteOutcome
{
    std::uint8_t exception = 0;
    std::int64_t readyAtUs = 0; // when the module answers (later than now for a delayed write)
    bool ok() const { return exception == 0; }
};

// The module's CMD 15 answer (DAT.1 status word, DAT.2 VALUE1, DAT.3 VALUE2).
struct CyclicValues
{
    std::uint16_t status = 0;
    std::int16_t value1 = 0;
    std::int16_t value2 = 0;
};

class HcsModule : public SimModel
{
public:
    // Attaches itself to `clock`; detaches on destruction. config.dictionary must be set.
    HcsModule(SimClock &clock, HcsModuleConfig config);
    ~HcsModule() override;
    HcsModule(const HcsModule &) = delete;
    HcsModule &operator=(const HcsModule &) = delete;

    const Dictionary &dictionary() const { return m_storage.dictionary(); }
    const HcsModuleConfig &config() const { return m_config; }
    hcs::Family family() const { return m_family; }
    const std::string &version() const { return m_version; }
    int mode() const { return m_mode; }
    std::optional<hcs::Profile> profile() const { return m_profile; }

    // OPAT: the fixed address (0 master, DIP switch 1..7); DMA: E22 as it is now.
    std::uint8_t address() const;
    // Sets the DIP switch (OPAT) or E22, committed to the EEPROM (a configuration, not a write).
    void setAddress(std::uint8_t address);

    // CMD 3 / FC 3: `count` consecutive IDs from `firstId`. Exceptions: 3 for a count outside
    // 1..8 (OPAT manual §2.1), 2 for an ID the module does not have or cannot read.
    ReadOutcome read(std::uint16_t firstId, std::uint16_t count) const;
    // CMD 6 / FC 6. Exceptions: 2 for an ID the module does not have, a read-only or not active
    // row; 3 out of range; 4 while the EEPROM is busy (EepromBusyPolicy::Refuse).
    WriteOutcome write(std::uint16_t id, std::uint16_t word);

    // CMD 15, this module's share of the request: the control byte (Din_1, Din_2, BUS_DISABLE
    // as the profile uses them; ignored while the hardware enable is off) and VALUE1 / VALUE2 to
    // the profile's rows. Returns 0 or exception 3 (a value outside its row's range).
    std::uint8_t applyCyclic(const hcs::ModuleSetpoints &setpoints);
    // The module's answer now: status word and the profile's two values.
    CyclicValues cyclicValues() const;

    // Terminal X3 "enable" and the bus (software) disable; a rising enable / falling disable
    // acknowledges latched errors whose cause has gone (DMA Profinet manual §4.5.1.1).
    void setHardwareEnable(bool on);
    bool hardwareEnable() const { return m_hwEnable; }
    void setBusDisable(bool on);
    bool busDisable() const { return m_busDisable; }
    bool din(int branch) const { return m_din[branch == 2 ? 1 : 0]; }

    // Module state word = ID 0xB0 (hcs/status_bits.h): HW_ENABLE, ERROR, BUS_DISABLE and the
    // error number or the signals the profile reports.
    std::uint16_t statusWord() const;
    std::optional<int> errorNumber() const; // the latched error's number, if any
    bool tripped() const;

    // Power: an unpowered module does not answer (the node reports it missing); switching it on
    // is a power cycle (EEPROM rows kept, everything else back to defaults, plant at rest).
    void setPowered(bool on);
    bool powered() const { return m_powered; }
    bool eepromBusy() const;
    std::int64_t eepromFreeAtUs() const { return m_eepromFreeAtUs; }

    // The image, for tests, tools and fault injection.
    HcsStorage &storage() { return m_storage; }
    const HcsStorage &storage() const { return m_storage; }
    OpenLoopPlant *openLoop(int branch);
    ClosedLoopPlant *closedLoop(int branch);

    void step(const SimStep &step) override;

private:
    void applyIdentity();
    void buildPlants();
    void refreshStatus();
    void acknowledgeErrors();
    void applyControl(std::uint8_t control);
    void writeSwitches(std::uint16_t word);
    std::uint8_t setCyclicValue(std::string_view name, std::int16_t value);
    std::uint8_t digitalSignals() const;
    std::int64_t now() const { return m_clock.nowUs(); }

    struct PendingCommit
    {
        int id = 0;
        std::int32_t value = 0;
        std::int64_t atUs = 0;
    };

    SimClock &m_clock;
    HcsModuleConfig m_config;
    hcs::Family m_family;
    std::string m_version;
    int m_mode;
    std::optional<hcs::Profile> m_profile;
    HcsStorage m_storage;
    std::array<std::unique_ptr<OpenLoopPlant>, 2> m_open;
    std::array<std::unique_ptr<ClosedLoopPlant>, 2> m_closed;
    std::vector<PendingCommit> m_pending;
    std::int64_t m_eepromFreeAtUs = 0;
    std::uint8_t m_dipAddress = 0;
    std::array<bool, 2> m_din{false, false};
    bool m_hwEnable = true;
    bool m_busDisable = false;
    bool m_powered = true;
    int m_idSwitches = -1, m_idErr = -1, m_idE22 = -1;
    std::array<int, 2> m_idController{-1, -1}; // C1.00, C2.00
};

// Family of a dictionary: "opat" → OPAT, every "dma-…" → DMA.
hcs::Family hcsFamilyOf(const Dictionary &dict);

} // namespace vt::dev::sim
