// HartDevice: addressing, status bytes, device-specific commands 128..133 and the process image.
// The universal commands are in hart_device_universal.cpp.
#include "sim/hart_device.h"

#include "dict/identify.h"
#include "dsp408/pzd.h"
#include "hart/device_specific.h"
#include "hart/texts.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

namespace vt::dev::sim {
namespace {

// HART-7 manual §4.3 control modes (db_ControlMode) → the function block whose command value,
// actual value and control deviation are live (dictionary names <block>_CommandValue, …).
std::string_view activeBlock(int controlMode)
{
    switch (controlMode) {
    case 1: return "vpoc";
    case 3:
    case 4:
    case -5: return "vprc";
    case 6: return "dcol";
    case 7: return "dsc";
    case 9: return "dpc";
    case -6:
    case -7:
    case -8: return "npc";
    default: return {};
    }
}

std::string name(std::string_view block, std::string_view suffix)
{
    return std::string(block) + "_" + std::string(suffix);
}

} // namespace

HartDevice::HartDevice(const Dictionary &sd7) : HartDevice(sd7, Options{})
{
}

HartDevice::HartDevice(const Dictionary &sd7, Options options)
    : m_options(std::move(options)), m_params(sd7), m_drive(m_options.drive)
{
    m_pollAddress = m_options.pollAddress;
    // Held as the wire carries them (packed ASCII: upper case, fixed length; long tag Latin-1).
    m_tag = hart::unpackAscii(hart::packAscii(m_options.tag, 6));
    m_descriptor = hart::unpackAscii(hart::packAscii(m_options.descriptor, 12));
    m_longTag = hart::latin1ToUtf8(hart::utf8ToLatin1(m_options.longTag, 32));
    m_date = m_options.date;
    m_params.set("db_Temperature", 35); // plausible board temperature, °C
}

void HartDevice::powerCycle()
{
    m_coldStart = {true, true};
    m_drive.powerOn();
}

hart::Address HartDevice::address() const
{
    return hart::longAddress(m_options.expandedDeviceType, m_options.deviceId);
}

hart::Identity HartDevice::identity() const
{
    hart::Identity id;
    id.expansionCode = 254;
    id.expandedDeviceType = m_options.expandedDeviceType;
    id.minRequestPreambles = m_options.minRequestPreambles;
    id.hartRevision = 7; // HART-7 manual §3.2: "All WANDFLUH HART devices support … revision 7"
    id.deviceRevision = m_options.deviceRevision;
    id.softwareRevision = m_options.softwareRevision;
    id.hardwareRevisionAndSignaling =
        static_cast<std::uint8_t>((m_options.hardwareRevision & 0x1F) << 3);
    id.flags = 0; // §5.1.1 "Flags, non defined at this time"
    id.deviceId = m_options.deviceId & hart::kMaxDeviceId;
    id.minResponsePreambles = m_options.minResponsePreambles;
    id.maxDeviceVariables = 4; // PV, SV, TV, QV (§5.1.4)
    id.configChangeCounter = m_configCounter;
    id.extendedStatus = m_errorCode != 0 ? 0x02 : 0x00; // HART "device variable alert"
    id.manufacturerId = kWandfluhHartManufacturer;
    id.privateLabel =
        kWandfluhHartManufacturer; // §5.1.13 remarks: "Private Label … = Manufacturer ID"
    id.deviceProfile = 1;          // HART process automation device
    return id;
}

std::uint8_t HartDevice::deviceStatus(bool primaryMaster) const
{
    const std::size_t m = masterIndex(primaryMaster);
    std::uint8_t status = 0;
    if (m_configChanged[m])
        status |= hart_status::kConfigChanged;
    if (m_coldStart[m])
        status |= hart_status::kColdStart;
    if (m_errorCode != 0)
        status |= hart_status::kMoreStatus;
    if (m_drive.faulted())
        status |= hart_status::kMalfunction;
    return status;
}

bool HartDevice::addressed(const hart::Address &address, std::uint8_t command) const
{
    // HART-7 manual §2.3 / ARCHITECTURE.md: short frame (poll address) for command 0 only.
    if (!address.isLong)
        return command == 0 && address.pollAddress == m_pollAddress;
    // The broadcast address (all 38 bits 0) is for "find by tag" (commands 11 and 21).
    if (address.expandedDeviceType == 0 && address.deviceId == 0)
        return command == 11 || command == 21;
    const hart::Address own = this->address();
    return address.expandedDeviceType == own.expandedDeviceType && address.deviceId == own.deviceId;
}

std::optional<hart::Frame> HartDevice::handle(const hart::Frame &request)
{
    if (request.type != hart::FrameType::Stx || !addressed(request.address, request.command))
        return std::nullopt;
    Reply reply = dispatch(request);
    if (reply.silent)
        return std::nullopt;
    const bool primary = request.address.primaryMaster;
    hart::Address to = request.address.isLong ? address() : hart::shortAddress(m_pollAddress);
    to.primaryMaster = primary;
    to.burst = false; // never in burst mode (no burst commands in §5.1)
    if (hart::isErrorResponse(reply.code))
        reply.data.clear(); // error responses carry the status bytes only; warnings their data
    hart::Frame response = hart::makeResponse(to, request.command, reply.code,
                                              deviceStatus(primary), std::move(reply.data));
    response.preambles = m_options.minResponsePreambles;
    m_coldStart[masterIndex(primary)] = false; // reported once to each master
    return response;
}

HartDevice::Reply HartDevice::dispatch(const hart::Frame &request)
{
    const std::uint8_t command = request.command;
    if (hart::isParameterCommand(command))
        return parameter(command, request.data);
    if (!hart::isUniversal(command))
        return {hart_rc::kNotImplemented, {}, false};
    auto payload = hart::decodeUniversal(command, false, request.data);
    if (!payload.ok())
        return {hart_rc::kTooFewDataBytes, {}, false};
    return universal(command, *payload, request.address.primaryMaster);
}

void HartDevice::configurationChanged()
{
    m_configChanged = {true, true};
    m_configCounter = static_cast<std::uint16_t>(m_configCounter + 1);
}

std::uint8_t HartDevice::refusal(ParamErrc error) const
{
    if (!m_options.commonResponseCodes)
        return hart_rc::kDeviceSpecific; // HART-7 manual §4.4.1: "6 device specific error"
    switch (error) {
    case ParamErrc::Unknown: return hart_rc::kInvalidSelection;
    case ParamErrc::AboveMax: return hart_rc::kTooLarge;
    case ParamErrc::BelowMin: return hart_rc::kTooSmall;
    case ParamErrc::NotReadable:
    case ParamErrc::ReadOnly:
    case ParamErrc::WrongState: return hart_rc::kAccessRestricted;
    case ParamErrc::WrongWidth:
    case ParamErrc::InvalidValue: return hart_rc::kDeviceSpecific;
    }
    return hart_rc::kDeviceSpecific;
}

// HART-7 manual §4.4.1: IND, PNU, instance (+ value); the command fixes the width.
HartDevice::Reply HartDevice::parameter(std::uint8_t command, const Bytes &data)
{
    auto access = hart::decodeParamAccess(command, false, data);
    if (!access.ok())
        return {hart_rc::kTooFewDataBytes, {}, false};
    const hart::ParamRef ref = access->ref;
    const ParamMeta *meta = m_params.find(ref.ind, ref.pnu, ref.instance);
    if (!meta)
        return {refusal(ParamErrc::Unknown), {}, false};
    if (hart::valueWidth(command) != wireBytes(meta->type))
        return {refusal(ParamErrc::WrongWidth), {}, false};
    if (hart::isWriteCommand(command)) {
        Reply r = writeParameter(*meta, fromWireBits(*meta, access->raw.value_or(0)));
        if (r.code != hart_rc::kOk)
            return r;
    } else if (!meta->readable()) {
        return {refusal(ParamErrc::NotReadable), {}, false};
    }
    double value = m_params.value(*meta);
    if (meta->name == "db_StatusWord")
        value =
            m_drive.statusWord() | (m_params.value("db_Local") != 0 ? dsp408::status::kLocal : 0);
    hart::ParamAccess out{command, ref, toWireBits(*meta, value)};
    auto bytes = hart::encodeParamAccess(out, true);
    return {hart_rc::kOk, bytes.ok() ? *bytes : Bytes{}, false};
}

HartDevice::Reply HartDevice::writeParameter(const ParamMeta &meta, double raw)
{
    if (auto error = m_params.checkWrite(meta, raw))
        return {refusal(*error), {}, false};
    if (isModeRow(meta) && !m_drive.configurable())
        return {refusal(ParamErrc::WrongState), {}, false};
    if (meta.name == "db_ResetDefault") {
        const auto word = static_cast<std::uint32_t>(static_cast<std::int64_t>(raw));
        if (word == kResetDefaultLoad) {
            m_params.resetDefaults();
            configurationChanged();
        } else if (word != 0) {
            return {refusal(ParamErrc::InvalidValue), {}, false};
        }
        return {};
    }
    m_params.set(meta, raw);
    if (meta.name == "db_ControlWord") {
        // HART-7 manual §4.2.1: the control word acts only in bus mode ("Device local" = 0).
        if (m_params.value("db_Local") == 0)
            m_drive.applyControlWord(static_cast<std::uint16_t>(raw));
        return {};
    }
    configurationChanged();
    return {};
}

void HartDevice::injectError(std::uint16_t code)
{
    m_errorCode = code;
    m_drive.setErrorPresent(code != 0);
}

void HartDevice::clearError()
{
    injectError(0);
}

float HartDevice::percentOfRange() const
{
    return (m_loopCurrentMa - 4.0f) / 16.0f * 100.0f;
}

void HartDevice::step(const SimStep &step)
{
    m_timeUs = step.timeUs;
    // Command value: the fieldbus row of the active block in bus device mode, else the analog
    // input 3 (4..20 mA = 0..100 % = 0..16384, HART-7 manual §3.2, §4.8 internal resolution).
    const std::string_view block = activeBlock(static_cast<int>(m_params.value("db_ControlMode")));
    const bool bus = m_params.value("db_Local") == 0 && m_params.value("db_DeviceMode", 1) == 1;
    const ParamMeta *command = block.empty() ? nullptr : m_params.find(name(block, "CommandValue"));
    if (bus && command)
        m_drive.setSetpoint(static_cast<std::int32_t>(m_params.value(*command)));
    else if (!bus)
        m_drive.setSetpoint(
            static_cast<std::int32_t>(std::lround(percentOfRange() / 100.0f * 16384.0f)));
    m_drive.step(step);
    if (block.empty())
        return;
    if (const ParamMeta *actual = m_params.find(name(block, "ActualValue")))
        m_params.set(*actual, m_drive.actual());
    if (const ParamMeta *deviation = m_params.find(name(block, "ControlDeviation")))
        m_params.set(*deviation, m_drive.setpoint() - m_drive.actual());
}

} // namespace vt::dev::sim
