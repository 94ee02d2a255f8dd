// HartDevice: the universal commands of the HART-7 manual §5.1 and the process values they
// report. Layouts are the codec's (hart/universal.h); the values are the simulator's choice where
// the manual only names the field (docs/SIMULATOR-WANDFLUH.md "HART process values").
#include "dict/identify.h"
#include "sim/hart_device.h"

#include <algorithm>
#include <variant>

namespace vt::dev::sim {
namespace {

constexpr std::uint8_t kUnitPercent = 57; // HART unit code "%"
constexpr std::uint8_t kUnitNotUsed = 250;
constexpr std::uint8_t kStatusGood = 0xC0; // device variable status: good, not limited
constexpr double kFullScale = 16384.0;     // HART-7 manual §4.8 internal bus resolution

// Closed-loop control modes (HART-7 manual §4.3): the PV is the measured actual value.
bool closedLoop(int controlMode)
{
    return controlMode == 4 || controlMode == 7 || controlMode == 9 || controlMode == -5;
}

float percent(double raw)
{
    return static_cast<float>(raw / kFullScale * 100.0);
}

Bytes encoded(const hart::Payload &payload)
{
    return hart::encodePayload(payload);
}

bool validDate(const hart::Date &date)
{
    return date.day >= 1 && date.day <= 31 && date.month >= 1 && date.month <= 12;
}

} // namespace

float HartDevice::primaryValue() const
{
    if (!closedLoop(static_cast<int>(m_params.value("db_ControlMode"))))
        return 0.0f; // §5.1.2: "0 (open loop)"
    return percent(m_drive.actualExact());
}

hart::DynamicVariables HartDevice::dynamicVariables() const
{
    const bool closed = closedLoop(static_cast<int>(m_params.value("db_ControlMode")));
    hart::DynamicVariables d;
    d.loopCurrentMa = m_loopCurrentMa;
    d.variables = {
        {closed ? kUnitPercent : kUnitNotUsed, primaryValue()}, // PV: actual value
        {kUnitPercent, percentOfRange()},                       // SV: analog command
        {kUnitPercent, percent(m_drive.setpoint())},            // TV: after the ramp
        {kUnitPercent, closed ? percent(m_drive.setpoint() - m_drive.actualExact()) : 0.0f}, // QV
    };
    return d;
}

// §5.1.8 command 9: device variable codes 0..3 (and the HART 7 codes 246..249) are PV..QV.
HartDevice::Reply HartDevice::deviceVariables(const hart::DeviceVariableCodes &codes) const
{
    const hart::DynamicVariables dyn = dynamicVariables();
    hart::DeviceVariables out;
    out.extendedStatus = identity().extendedStatus;
    for (const std::uint8_t code : codes.codes) {
        const int slot = code >= 246 && code <= 249 ? code - 246 : code;
        if (slot < 0 || slot > 3)
            return {hart_rc::kInvalidSelection, {}, false};
        const hart::UnitValue &v = dyn.variables[static_cast<std::size_t>(slot)];
        out.variableSlots.push_back({code, 0, v.unit, v.value, kStatusGood});
    }
    // Time stamp in 1/32 ms, wrapping like the device's 32-bit counter.
    out.timestamp = static_cast<std::uint32_t>((m_timeUs * 32 / 1000) & 0xFFFFFFFF);
    return {hart_rc::kOk, encoded(out), false};
}

// §5.1.22 command 48: bytes 0..1 = db_ErrorCode, byte 2 = device state (our layout; the manual
// names the bytes "device specific status" only), 6 = extended status, 7 = operating mode.
hart::AdditionalStatus HartDevice::additionalStatus() const
{
    Bytes b(25, 0);
    b[0] = static_cast<std::uint8_t>(m_errorCode >> 8);
    b[1] = static_cast<std::uint8_t>(m_errorCode);
    b[2] = static_cast<std::uint8_t>(m_drive.state());
    b[6] = identity().extendedStatus;
    return hart::AdditionalStatus{std::move(b)};
}

HartDevice::Reply HartDevice::universal(std::uint8_t command, const hart::Payload &payload,
                                        bool primaryMaster)
{
    switch (command) {
    case 0: return {hart_rc::kOk, encoded(identity()), false};
    case 1: return {hart_rc::kOk, encoded(dynamicVariables().variables[0]), false};
    case 2:
        return {hart_rc::kOk, encoded(hart::LoopCurrent{m_loopCurrentMa, percentOfRange()}), false};
    case 3: return {hart_rc::kOk, encoded(dynamicVariables()), false};
    case 6: {
        const auto &c = std::get<hart::LoopConfiguration>(payload);
        if (c.pollAddress > 15) // §3.4 "Bus Node Address 0 … 15"
            return {hart_rc::kInvalidSelection, {}, false};
        if (c.loopCurrentMode > 1)
            return {hart_rc::kInvalidMode, {}, false};
        m_pollAddress = c.pollAddress;
        m_loopCurrentMode = c.loopCurrentMode;
        configurationChanged();
        return {hart_rc::kOk, encoded(hart::LoopConfiguration{m_pollAddress, m_loopCurrentMode}),
                false};
    }
    case 7:
        return {hart_rc::kOk, encoded(hart::LoopConfiguration{m_pollAddress, m_loopCurrentMode}),
                false};
    case 8:
        return {hart_rc::kOk, encoded(hart::VariableClassifications{}), false}; // "not classified"
    case 9: return deviceVariables(std::get<hart::DeviceVariableCodes>(payload));
    case 11:
        // Answered only by the device whose tag matches; the others stay silent (HART rule).
        if (std::get<hart::Tag>(payload).tag != m_tag)
            return {hart_rc::kOk, {}, true};
        return {hart_rc::kOk, encoded(identity()), false};
    case 12: return {hart_rc::kOk, encoded(hart::Message{m_message}), false};
    case 13:
        return {hart_rc::kOk, encoded(hart::TagDescriptorDate{m_tag, m_descriptor, m_date}), false};
    case 14:
        return {hart_rc::kOk,
                encoded(hart::TransducerInfo{m_options.deviceId & hart::kMaxDeviceId, kUnitPercent,
                                             100.0f, -100.0f, 1.0f}),
                false};
    case 15: {
        const bool closed = closedLoop(static_cast<int>(m_params.value("db_ControlMode")));
        hart::DeviceInfo info; // §5.1.13 remarks
        info.alarmSelection = 1;
        info.transferFunction = 0;
        info.rangeUnit = closed ? kUnitPercent : kUnitNotUsed;
        info.upperRange = closed ? 100.0f : 0.0f;
        info.lowerRange = closed ? -100.0f : 0.0f;
        info.damping = 0.0f;
        info.writeProtect = 251;
        info.reserved = 250;
        info.analogChannelFlags = 0;
        return {hart_rc::kOk, encoded(info), false};
    }
    case 16: return {hart_rc::kOk, encoded(hart::FinalAssemblyNumber{m_finalAssembly}), false};
    case 17:
        // Stored as the wire holds it (packed ASCII: upper case, 32 characters).
        m_message = hart::unpackAscii(hart::packAscii(std::get<hart::Message>(payload).text, 24));
        configurationChanged();
        return {hart_rc::kOk, encoded(hart::Message{m_message}), false};
    case 18: {
        const auto &t = std::get<hart::TagDescriptorDate>(payload);
        if (!validDate(t.date))
            return {hart_rc::kInvalidDate, {}, false};
        m_tag = t.tag;
        m_descriptor = t.descriptor;
        m_date = t.date;
        configurationChanged();
        return {hart_rc::kOk, encoded(hart::TagDescriptorDate{m_tag, m_descriptor, m_date}), false};
    }
    case 19:
        m_finalAssembly = std::get<hart::FinalAssemblyNumber>(payload).number & hart::kMaxDeviceId;
        configurationChanged();
        return {hart_rc::kOk, encoded(hart::FinalAssemblyNumber{m_finalAssembly}), false};
    case 20: return {hart_rc::kOk, encoded(hart::LongTag{m_longTag}), false};
    case 21:
        if (std::get<hart::LongTag>(payload).text != m_longTag)
            return {hart_rc::kOk, {}, true};
        return {hart_rc::kOk, encoded(identity()), false};
    case 22:
        m_longTag =
            hart::latin1ToUtf8(hart::utf8ToLatin1(std::get<hart::LongTag>(payload).text, 32));
        configurationChanged();
        return {hart_rc::kOk, encoded(hart::LongTag{m_longTag}), false};
    case 38: {
        // §5.1.21; HART 7: the flag is reset only when the counter matches (HART 5 masters send
        // none). The flag belongs to the master that asks.
        const auto &c = std::get<hart::ConfigChangeCounter>(payload);
        if (c.counter && *c.counter != m_configCounter)
            return {hart_rc::kCounterMismatch, {}, false};
        m_configChanged[masterIndex(primaryMaster)] = false;
        return {hart_rc::kOk, encoded(hart::ConfigChangeCounter{m_configCounter}), false};
    }
    case 48: {
        // §5.1.22: the master may send the status bytes it last read ("Data bytes write 0 - 5:
        // Device Specific Status 6: Extended Device Status …"); HART 7 answers with the present
        // bytes and the warning 14 when they differ, so the master learns the status changed.
        const hart::AdditionalStatus now = additionalStatus();
        const auto *asked = std::get_if<hart::AdditionalStatus>(&payload);
        const Bytes sent = asked ? asked->bytes : Bytes{};
        const bool differs =
            !sent.empty() &&
            !std::equal(sent.begin(), sent.end(), now.bytes.begin(),
                        now.bytes.begin() +
                            std::ptrdiff_t(std::min(sent.size(), now.bytes.size())));
        return {differs ? hart_rc::kStatusBytesMismatch : hart_rc::kOk, encoded(now), false};
    }
    default: return {hart_rc::kNotImplemented, {}, false};
    }
}

} // namespace vt::dev::sim
