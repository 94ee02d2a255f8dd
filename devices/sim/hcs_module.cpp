#include "sim/hcs_module.h"

#include "dict/cooking.h"
#include "hcs/node_rules.h"
#include "hcs/status_bits.h"
#include "sim/hcs_codes.h"

#include <charconv>

namespace vt::dev::sim {
namespace {

int parseInt(const std::string &text, int fallback)
{
    int value = fallback;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() ? value : fallback;
}

// C1.00 = 2 / 4: the remote loop controller, whose activity Dout_1 / Dout_2 report (DMA Profinet
// manual §4.5.1.3 "Dout_1 Indicates that the function remote loop controller is active").
bool remoteController(std::int32_t c100)
{
    return c100 == 2 || c100 == 4;
}

// Parameter 0xB0 bits a master may set (dictionary 0xB0: "Writable: Din_1, Din_2 and Bus Disable
// Card; the other bits are read only").
constexpr std::uint16_t kSwitchDin1 = 0x0001;
constexpr std::uint16_t kSwitchDin2 = 0x0010;

} // namespace

hcs::Family hcsFamilyOf(const Dictionary &dict)
{
    return dict.family.rfind("opat", 0) == 0 ? hcs::Family::Opat : hcs::Family::Dma;
}

HcsModule::HcsModule(SimClock &clock, HcsModuleConfig config)
    : m_clock(clock), m_config(std::move(config)), m_family(hcsFamilyOf(*m_config.dictionary)),
      m_version(!m_config.version.empty()               ? m_config.version
                : m_config.dictionary->versions.empty() ? std::string()
                                                        : m_config.dictionary->versions.front()),
      m_mode(m_config.mode != 0 ? m_config.mode
             : m_config.dictionary->modes.empty()
                 ? 0
                 : parseInt(m_config.dictionary->modes.front(), 0)),
      m_profile(hcs::profileFor(m_family, parseInt(m_version, 0), m_mode)),
      m_storage(*m_config.dictionary, m_version, std::to_string(m_mode)),
      m_dipAddress(m_config.address), m_hwEnable(m_config.hardwareEnable)
{
    auto idOf = [this](std::string_view name) {
        const ParamMeta *row = m_storage.find(name);
        return row ? *row->id : -1;
    };
    m_idSwitches = idOf("0xB0");
    m_idErr = idOf("ERR");
    m_idE22 = idOf("E22");
    m_idController = {idOf("C1.00"), idOf("C2.00")};
    applyIdentity();
    setAddress(m_config.address);
    buildPlants();
    refreshStatus();
    m_clock.attach(*this);
}

HcsModule::~HcsModule()
{
    m_clock.detach(*this);
}

void HcsModule::applyIdentity()
{
    // Vers = version × 100 (docs/DICTIONARY.md "Identification"), E00 = mode: fixed by the
    // firmware, so they survive a power cycle whatever their persistence says.
    const int versRaw =
        m_config.versionRaw != 0 ? m_config.versionRaw : parseInt(m_version, 0) * 100;
    for (const auto &[name, value] :
         {std::pair<std::string_view, int>{"Vers", versRaw}, {"E00", m_mode}}) {
        if (const ParamMeta *row = m_storage.find(name)) {
            m_storage.setRaw(*row->id, value);
            m_storage.commit(*row->id, value);
        }
    }
}

void HcsModule::buildPlants()
{
    m_open = {};
    m_closed = {};
    const auto closed = [this](int branch) {
        PlantConfig c;
        c.branch = branch;
        m_closed[static_cast<std::size_t>(branch - 1)] = std::make_unique<ClosedLoopPlant>(
            dictionary(), m_storage, m_storage, makeAxisForMode(m_mode, branch), c);
    };
    const auto open = [this](int branch) {
        PlantConfig c;
        c.branch = branch;
        m_open[static_cast<std::size_t>(branch - 1)] =
            std::make_unique<OpenLoopPlant>(dictionary(), m_storage, m_storage, c);
    };
    switch (m_mode) {
    case 1: open(1); break; // one valve with two solenoids (DMA V13 / V15)
    case 2:
        open(1);
        open(2);
        break; // two valves with one solenoid each (DMA V22)
    case 6:
    case 8:
        closed(1);
        closed(2);
        break;                 // two closed loops (OPAT, DMA V32)
    default: closed(1); break; // modes 3 / 4
    }
}

std::uint8_t HcsModule::address() const
{
    if (m_family == hcs::Family::Dma && m_idE22 >= 0)
        return static_cast<std::uint8_t>(m_storage.raw(m_idE22));
    return m_dipAddress;
}

void HcsModule::setAddress(std::uint8_t address)
{
    m_dipAddress = address;
    // OPAT V31 shows its DIP switch in E22 ("CAN slave address", read only); DMA: E22 itself.
    if (m_idE22 >= 0) {
        m_storage.setRaw(m_idE22, address);
        m_storage.commit(m_idE22, address);
    }
}

ReadOutcome HcsModule::read(std::uint16_t firstId, std::uint16_t count) const
{
    if (!hcs::withinReadLimit(count))
        return {{}, exce::kBadCount};
    ReadOutcome out;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t id = firstId + i;
        const ParamMeta *row = id <= 0xFFFF ? m_storage.meta(static_cast<int>(id)) : nullptr;
        if (!row || !row->readable()) {
            if (m_config.strictBlockReads)
                return {{}, exce::kWrongId};
            out.values.push_back(0);
            continue;
        }
        out.values.push_back(m_storage.word(static_cast<int>(id)));
    }
    return out;
}

WriteOutcome HcsModule::write(std::uint16_t id, std::uint16_t word)
{
    const std::int64_t t = now();
    const ParamMeta *row = m_storage.meta(id);
    if (!row)
        return {exce::kWrongId, t};
    const std::int32_t value = HcsStorage::fromWord(*row, word);
    if (const auto error = checkWrite(*row, value))
        return {error->kind == CookError::Kind::NotWritable ? exce::kWrongId : exce::kWrongData, t};
    if (static_cast<int>(id) == m_idSwitches) {
        writeSwitches(static_cast<std::uint16_t>(value));
        return {exce::kNone, t};
    }
    if (!HcsStorage::isEeprom(*row) || m_config.eepromWriteUs <= 0) {
        m_storage.setRaw(id, value);
        return {exce::kNone, t};
    }
    // DMA Profinet manual §3.4.1: up to 25 ms of EEPROM time per parameter.
    std::int64_t start = t;
    if (t < m_eepromFreeAtUs) {
        if (m_config.eepromBusy == EepromBusyPolicy::Refuse)
            return {exce::kWriteFailed, t};
        start = m_eepromFreeAtUs;
    }
    m_eepromFreeAtUs = start + m_config.eepromWriteUs;
    m_storage.setRaw(id, value);
    m_pending.push_back({id, value, m_eepromFreeAtUs});
    return {exce::kNone, start};
}

void HcsModule::writeSwitches(std::uint16_t word)
{
    const std::uint8_t used = m_profile ? hcs::profileInfo(*m_profile).controlBits : 0;
    if ((used & hcs::kControlDin1) != 0)
        m_din[0] = (word & kSwitchDin1) != 0;
    if ((used & hcs::kControlDin2) != 0)
        m_din[1] = (word & kSwitchDin2) != 0;
    setBusDisable((word & hcs::kStatusBusDisable) != 0);
    refreshStatus();
}

void HcsModule::applyControl(std::uint8_t control)
{
    const std::uint8_t used =
        m_profile ? hcs::profileInfo(*m_profile).controlBits : hcs::kControlBusDisable;
    m_din[0] = (control & used & hcs::kControlDin1) != 0;
    m_din[1] = (control & used & hcs::kControlDin2) != 0;
    setBusDisable((control & hcs::kControlBusDisable) != 0);
}

std::uint8_t HcsModule::setCyclicValue(std::string_view name, std::int16_t value)
{
    const ParamMeta *row = m_storage.find(name);
    if (!row)
        return exce::kNone; // the profile's row is not in this family: the value is not used
    if (checkRange(*row, value))
        return exce::kWrongData;
    m_storage.setRaw(*row->id, value);
    return exce::kNone;
}

std::uint8_t HcsModule::applyCyclic(const hcs::ModuleSetpoints &setpoints)
{
    if (!m_profile)
        return exce::kCommandNotSupported;
    const hcs::ProfileInfo &info = hcs::profileInfo(*m_profile);
    // Check both values before taking either: a refused telegram changes nothing.
    for (const auto &[name, value] : {std::pair{info.request1.parameter, setpoints.value1},
                                      std::pair{info.request2.parameter, setpoints.value2}}) {
        const ParamMeta *row = m_storage.find(name);
        if (row && checkRange(*row, value))
            return exce::kWrongData;
    }
    // OPAT manual §3.5.2, DMA Profinet manual §4.5.3: "Can be set only if the hardware enable is
    // active"; while it is inactive the control byte is held at 0x00.
    if (m_hwEnable)
        applyControl(setpoints.control);
    setCyclicValue(info.request1.parameter, setpoints.value1);
    setCyclicValue(info.request2.parameter, setpoints.value2);
    refreshStatus();
    return exce::kNone;
}

CyclicValues HcsModule::cyclicValues() const
{
    CyclicValues v;
    v.status = statusWord();
    if (m_profile) {
        const hcs::ProfileInfo &info = hcs::profileInfo(*m_profile);
        v.value1 = static_cast<std::int16_t>(m_storage.get(info.response1.parameter));
        v.value2 = static_cast<std::int16_t>(m_storage.get(info.response2.parameter));
    }
    return v;
}

void HcsModule::setHardwareEnable(bool on)
{
    if (on && !m_hwEnable)
        acknowledgeErrors();
    if (!on) {
        // "The special function byte will be set to internal 0x00 (reset) when the hardware
        // enable is inactive" (DMA Profinet manual §4.5.3).
        m_din = {false, false};
        m_busDisable = false;
    }
    m_hwEnable = on;
    refreshStatus();
}

void HcsModule::setBusDisable(bool on)
{
    // DMA Profinet manual §4.5.1.1: "Setting and resetting of the Bits (0x80) BUS_DISABLE"
    // acknowledges an error once its cause has gone.
    if (m_busDisable && !on)
        acknowledgeErrors();
    m_busDisable = on;
    refreshStatus();
}

void HcsModule::acknowledgeErrors()
{
    for (std::size_t b = 0; b < 2; ++b) {
        if (m_open[b])
            m_open[b]->acknowledgeErrors();
        if (m_closed[b])
            m_closed[b]->acknowledgeErrors();
    }
}

bool HcsModule::tripped() const
{
    for (std::size_t b = 0; b < 2; ++b) {
        if (m_open[b] && m_open[b]->errors().tripped())
            return true;
        if (m_closed[b] && m_closed[b]->errors().tripped())
            return true;
    }
    return false;
}

std::optional<int> HcsModule::errorNumber() const
{
    for (std::size_t b = 0; b < 2; ++b) {
        const int branch = static_cast<int>(b) + 1;
        const ErrorLatch *latch = m_open[b]     ? &m_open[b]->errors()
                                  : m_closed[b] ? &m_closed[b]->errors()
                                                : nullptr;
        if (!latch || !latch->tripped())
            continue;
        const ErrorTable table = m_family == hcs::Family::Opat ? ErrorTable::Opat : ErrorTable::Dma;
        // An error without a number in the manual's table reports 1, the DMA table's "error of
        // operation (general error)" (an assumption; docs/SIMULATOR.md).
        return latch->latched().reportedNumber(table, branch).value_or(1);
    }
    return std::nullopt;
}

std::uint8_t HcsModule::digitalSignals() const
{
    std::uint8_t s = 0;
    for (std::size_t b = 0; b < 2; ++b) {
        if (m_din[b])
            s |= b == 0 ? hcs::kStatusDin1 : hcs::kStatusDin2;
        const ClosedLoopPlant *plant = m_closed[b].get();
        if (plant && m_idController[b] >= 0 && plant->loop().closed &&
            remoteController(m_storage.raw(m_idController[b])))
            s |= b == 0 ? hcs::kStatusDout1 : hcs::kStatusDout2;
    }
    // DKOMP_x: the comparators are not modelled (docs/SIMULATOR-PLANT.md "Not modelled").
    const std::uint8_t used = m_profile ? hcs::profileInfo(*m_profile).statusLowBits : 0xFF;
    return static_cast<std::uint8_t>(s & used);
}

std::uint16_t HcsModule::statusWord() const
{
    std::uint16_t word = 0;
    if (m_hwEnable)
        word |= hcs::kStatusHwEnable;
    if (m_busDisable)
        word |= hcs::kStatusBusDisable;
    if (const auto number = errorNumber()) {
        word |= hcs::kStatusError;
        word |= static_cast<std::uint16_t>(*number & 0xFF);
    } else {
        word |= digitalSignals();
    }
    return word;
}

void HcsModule::refreshStatus()
{
    if (m_idSwitches >= 0)
        m_storage.setRaw(m_idSwitches, statusWord());
    if (m_idErr >= 0)
        m_storage.setRaw(m_idErr, errorNumber().value_or(0));
}

bool HcsModule::eepromBusy() const
{
    return now() < m_eepromFreeAtUs;
}

void HcsModule::setPowered(bool on)
{
    if (on == m_powered)
        return;
    m_powered = on;
    if (!on) {
        m_pending.clear(); // a write still in the EEPROM is lost
        m_eepromFreeAtUs = 0;
        return;
    }
    m_storage.restoreAfterPowerCycle();
    applyIdentity();
    if (m_family == hcs::Family::Opat)
        setAddress(m_dipAddress); // the DIP switch, shown in E22 (V31)
    m_din = {false, false};
    m_busDisable = false;
    buildPlants();
    refreshStatus();
}

OpenLoopPlant *HcsModule::openLoop(int branch)
{
    return branch == 1 || branch == 2 ? m_open[static_cast<std::size_t>(branch - 1)].get()
                                      : nullptr;
}

ClosedLoopPlant *HcsModule::closedLoop(int branch)
{
    return branch == 1 || branch == 2 ? m_closed[static_cast<std::size_t>(branch - 1)].get()
                                      : nullptr;
}

void HcsModule::step(const SimStep &step)
{
    if (!m_powered)
        return;
    const bool on = m_hwEnable && !m_busDisable;
    for (std::size_t b = 0; b < 2; ++b) {
        if (m_open[b]) {
            m_open[b]->setEnabled(on);
            m_open[b]->step(step);
        }
        if (m_closed[b]) {
            m_closed[b]->setEnabled(on);
            m_closed[b]->setDin(m_din[b]);
            m_closed[b]->step(step);
        }
    }
    const auto due = [&](const PendingCommit &c) { return c.atUs <= step.timeUs; };
    for (const PendingCommit &c : m_pending)
        if (due(c))
            m_storage.commit(c.id, c.value);
    std::erase_if(m_pending, due);
    refreshStatus();
}

} // namespace vt::dev::sim
