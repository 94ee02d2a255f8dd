#include "sim/dsp408_device.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

using dsp408::Pkw;

namespace {

dsp408::ParamLength lengthOf(const ParamMeta &meta)
{
    return static_cast<dsp408::ParamLength>(wireBytes(meta.type));
}

} // namespace

std::uint16_t pkwErrorCode(ParamErrc error)
{
    using dsp408::PkwError;
    switch (error) {
    case ParamErrc::Unknown: return static_cast<std::uint16_t>(PkwError::UndefinedPnu);
    case ParamErrc::ReadOnly: return static_cast<std::uint16_t>(PkwError::NotChangeable);
    case ParamErrc::BelowMin:
    case ParamErrc::AboveMax:
    case ParamErrc::InvalidValue: return static_cast<std::uint16_t>(PkwError::ValueRange);
    case ParamErrc::WrongWidth: return static_cast<std::uint16_t>(PkwError::DataType);
    case ParamErrc::NotReadable:
    case ParamErrc::WrongState: return static_cast<std::uint16_t>(PkwError::Other);
    }
    return static_cast<std::uint16_t>(PkwError::Other);
}

Dsp408Device::Dsp408Device(const Dictionary &ed1) : Dsp408Device(ed1, Options{})
{
}

Dsp408Device::Dsp408Device(const Dictionary &ed1, Options options)
    : m_options(options), m_params(ed1), m_stored(ed1), m_drive(options.drive)
{
    syncWindow();
}

std::uint16_t Dsp408Device::statusWord() const
{
    std::uint16_t word = m_drive.statusWord();
    if (local())
        word = static_cast<std::uint16_t>(word | dsp408::status::kLocal);
    return word;
}

std::optional<ParamErrc> Dsp408Device::read(const ParamMeta &meta, double &raw) const
{
    if (!meta.readable())
        return ParamErrc::NotReadable;
    if (meta.name == "db_StatusWord")
        raw = statusWord();
    else if (meta.name == "dpc_ActualVal")
        raw = m_drive.actual();
    else if (meta.name == "dpc_CtrlDeviationVal")
        raw = static_cast<double>(m_drive.setpoint()) - m_drive.actual();
    else
        raw = m_params.value(meta);
    return std::nullopt;
}

std::optional<ParamErrc> Dsp408Device::write(const ParamMeta &meta, double raw)
{
    if (auto error = m_params.checkWrite(meta, raw))
        return error;
    if (isModeRow(meta)) {
        // §4.2.2: modes change in INIT / DISABLED only; §4.3.1: "preset value via bus" needs
        // bus control, and local control forces "preset value locally".
        if (!m_drive.configurable())
            return ParamErrc::WrongState;
        if (meta.name == "db_DeviceMode" && raw == 1 && local())
            return ParamErrc::WrongState;
        if (meta.name == "db_Local" && raw == 1)
            m_params.set("db_DeviceMode", 2);
    }
    if (meta.name == "db_StoreParameter" || meta.name == "db_ResetDefault")
        return writeCommand(meta, raw);
    if (meta.name == "db_ControlWord") {
        applyControlWord(static_cast<std::uint16_t>(raw));
        return std::nullopt;
    }
    if (meta.name == "dpc_SetpointVal") {
        applyBusSetpoint(static_cast<std::int32_t>(raw));
        m_params.set(meta, raw);
        return std::nullopt;
    }
    m_params.set(meta, raw);
    syncWindow();
    return std::nullopt;
}

// §4.8.8 / §4.8.9: 0 does nothing, 'save' / 'load' act, anything else is refused.
std::optional<ParamErrc> Dsp408Device::writeCommand(const ParamMeta &meta, double raw)
{
    const auto word = static_cast<std::uint32_t>(static_cast<std::int64_t>(raw));
    if (word == 0)
        return std::nullopt;
    if (meta.name == "db_StoreParameter" && word == kStoreParameterSave) {
        m_stored = m_params;
        return std::nullopt;
    }
    if (meta.name == "db_ResetDefault" && word == kResetDefaultLoad) {
        const double controlWord = m_params.value("db_ControlWord");
        const double errorCode = m_params.value("db_ErrorCode");
        m_params.resetDefaults();
        m_params.set("db_ControlWord", controlWord); // live values, not settings
        m_params.set("db_ErrorCode", errorCode);
        syncWindow();
        return std::nullopt;
    }
    return ParamErrc::InvalidValue;
}

void Dsp408Device::applyControlWord(std::uint16_t controlWord)
{
    if (local())
        return; // §4.2.1: in local mode every fieldbus value but "Local" is ignored
    m_params.set("db_ControlWord", controlWord);
    m_drive.applyControlWord(controlWord);
}

void Dsp408Device::applyBusSetpoint(std::int32_t raw)
{
    if (local() || m_params.value("db_DeviceMode") != 1)
        return;
    const ParamMeta *meta = m_params.find("dpc_SetpointVal");
    double value = raw;
    if (meta) {
        const Limits l = m_params.limits(*meta);
        value = std::clamp(value, l.min, l.max);
        m_params.set(*meta, value);
    }
    m_drive.setSetpoint(static_cast<std::int32_t>(value));
}

void Dsp408Device::setLocalControlWord(std::uint16_t controlWord)
{
    if (local())
        m_drive.applyControlWord(controlWord);
}

void Dsp408Device::setLocalSetpoint(std::int32_t raw)
{
    m_localSetpoint = raw;
}

void Dsp408Device::injectError(std::uint16_t code)
{
    m_params.set("db_ErrorCode", code);
    m_drive.setErrorPresent(code != 0);
}

void Dsp408Device::powerCycle()
{
    const Dictionary &dict = m_params.dictionary();
    for (const ParamMeta &meta : dict.params) {
        const bool kept = meta.persistence == Persistence::Eeprom;
        m_params.set(meta, kept ? m_stored.value(meta) : Dsp408ParamStore::defaultOf(meta));
    }
    m_lastRequest.reset();
    m_drive.setErrorPresent(false);
    m_drive.setSetpoint(0);
    m_drive.powerOn();
    syncWindow();
}

void Dsp408Device::syncWindow()
{
    const auto threshold = static_cast<std::int32_t>(m_params.value("dpc_window_ThresholdVal"));
    const auto hysteresis =
        static_cast<std::int32_t>(m_params.value("dpc_window_ThresholdHystVal"));
    m_drive.setTargetWindow(threshold, hysteresis);
}

Pkw Dsp408Device::unknownRequest(std::uint8_t ind, std::uint16_t pnu)
{
    return dsp408::errorResponse(ind, pnu, static_cast<std::uint16_t>(dsp408::PkwError::Other));
}

Pkw Dsp408Device::handlePkw(const Pkw &request)
{
    const auto ak = static_cast<dsp408::RequestId>(request.ak);
    const auto writeLength = dsp408::requestLength(request.ak);
    if (writeLength && m_lastRequest && *m_lastRequest == request)
        return m_lastResponse;
    Pkw response;
    const ParamMeta *meta = m_params.find(request.ind, request.pnu);
    if (ak == dsp408::RequestId::None) {
        response.ind = request.ind;
        response.pnu = request.pnu; // AK 0 "no instruction" → response AK 0
    } else if (!meta) {
        response =
            dsp408::errorResponse(request.ind, request.pnu, pkwErrorCode(ParamErrc::Unknown));
    } else if (ak == dsp408::RequestId::Read) {
        double value = 0;
        if (auto error = read(*meta, value))
            response = dsp408::errorResponse(request.ind, request.pnu, pkwErrorCode(*error));
        else
            response = dsp408::valueResponse(request.ind, request.pnu, lengthOf(*meta),
                                             toWireBits(*meta, value));
    } else if (!meta->writable()) {
        response =
            dsp408::errorResponse(request.ind, request.pnu, pkwErrorCode(ParamErrc::ReadOnly));
    } else if (!writeLength || *writeLength != lengthOf(*meta)) {
        response =
            dsp408::errorResponse(request.ind, request.pnu, pkwErrorCode(ParamErrc::WrongWidth));
    } else {
        const double raw = fromWireBits(*meta, dsp408::pweValue(request.pwe, *writeLength));
        if (auto error = write(*meta, raw)) {
            response = dsp408::errorResponse(request.ind, request.pnu, pkwErrorCode(*error));
        } else {
            // The positive answer carries the value the parameter now holds (§4.6.1 example 1).
            double now = raw;
            if (meta->readable())
                (void)read(*meta, now);
            response = dsp408::valueResponse(request.ind, request.pnu, lengthOf(*meta),
                                             toWireBits(*meta, now));
        }
    }
    m_lastRequest = request;
    m_lastResponse = response;
    return response;
}

dsp408::PzdActual Dsp408Device::handlePzd(const dsp408::PzdSetpoint &request)
{
    applyBusSetpoint(request.setpoint);
    applyControlWord(request.controlWord);
    return {statusWord(), actualValue()};
}

dsp408::ResponseTelegram Dsp408Device::exchange(const dsp408::RequestTelegram &request)
{
    dsp408::ResponseTelegram response;
    if (request.pkw)
        response.pkw = handlePkw(*request.pkw);
    response.pzd = handlePzd(request.pzd);
    return response;
}

void Dsp408Device::step(const SimStep &step)
{
    if (local() || m_params.value("db_DeviceMode") != 1)
        m_drive.setSetpoint(m_localSetpoint);
    m_drive.step(step);
}

} // namespace vt::dev::sim
