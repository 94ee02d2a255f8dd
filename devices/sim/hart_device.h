// Simulated Wandfluh SD7 (SD733 by default) as a HART-7 field device: answers one request frame
// at a time (HartServer feeds it from a byte stream). Covers the HART-7 manual's universal
// commands (§5.1: 0, 1, 2, 3, 6, 7, 8, 9, 11–22, 38, 48), the device-specific commands 128..133
// by IND/PNU/instance against the wandfluh-sd7 dictionary (§4.4.1, §5.2), the status bytes of
// §4.4.1 and the addressing of §2.3 (short frame by poll address for command 0, long frame by
// expanded device type + device id afterwards). Behaviour and assumptions:
// docs/SIMULATOR-WANDFLUH.md. Owner: whoever builds the simulator; single-threaded.
#pragma once

#include "hart/data_types.h"
#include "hart/frame.h"
#include "hart/universal.h"
#include "sim/dsp408_drive.h"
#include "sim/dsp408_param_store.h"
#include "sim/sim_clock.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace vt::dev::sim {

// HART-7 manual §4.4.1 "status byte 1" (0, 5, 6) and the HART common / command-specific codes
// the manual leaves out but a master must understand.
namespace hart_rc {
inline constexpr std::uint8_t kOk = 0;
inline constexpr std::uint8_t kInvalidSelection = 2; // e.g. cmd 6 poll address > 15, cmd 9 code
inline constexpr std::uint8_t kTooLarge = 3;
inline constexpr std::uint8_t kTooSmall = 4;
inline constexpr std::uint8_t kTooFewDataBytes = 5;      // manual: "wrong byte count"
inline constexpr std::uint8_t kDeviceSpecific = 6;       // manual: "device specific error"
inline constexpr std::uint8_t kInvalidDate = 9;          // cmd 18
inline constexpr std::uint8_t kCounterMismatch = 9;      // cmd 38 (HART 7)
inline constexpr std::uint8_t kInvalidMode = 12;         // cmd 6 loop current mode
inline constexpr std::uint8_t kStatusBytesMismatch = 14; // cmd 48, a warning (HART 7)
inline constexpr std::uint8_t kAccessRestricted = 16;
inline constexpr std::uint8_t kNotImplemented = 64;
} // namespace hart_rc

// HART-7 manual §4.4.1 "status byte 2" (field device status).
namespace hart_status {
inline constexpr std::uint8_t kMoreStatus = 0x10;
inline constexpr std::uint8_t kColdStart = 0x20;
inline constexpr std::uint8_t kConfigChanged = 0x40;
inline constexpr std::uint8_t kMalfunction = 0x80;
} // namespace hart_status

class HartDevice : public SimModel
{
public:
    // Delivery state after HART-7 manual §3.4 and §6.4 (the §6.4 list is shifted by one line in
    // the OCR; docs/dictionary-notes/sd7.md reads it).
    struct Options
    {
        std::uint16_t expandedDeviceType = 58352; // SD733 (SD736: 58353)
        std::uint32_t deviceId = 2412345;         // "year (2 digits) + serial number (5 digits)"
        std::uint8_t pollAddress = 0;             // "Bus Node Address 0 … 15"
        std::uint8_t deviceRevision = 1;
        std::uint8_t softwareRevision = 1;
        std::uint8_t hardwareRevision = 1; // 5 bits; signalling code 0 (Bell 202 current)
        std::uint8_t minRequestPreambles = 5;
        std::uint8_t minResponsePreambles = 5;
        std::string tag = "WAGSD733";
        std::string longTag = "Wandfluh AG - SD733";
        std::string descriptor = "WAG ELECTRONIC"; // packed ASCII has no lower case
        hart::Date date{15, 3, 124};               // day of testing (assumed)
        // false: device-specific refusals answer 6 as the manual's table says; true: the HART
        // common codes (2 unknown parameter, 3/4 range, 16 access).
        bool commonResponseCodes = false;
        Dsp408Drive::Options drive{};
    };

    explicit HartDevice(const Dictionary &sd7);
    HartDevice(const Dictionary &sd7, Options options);

    // One decoded request (STX). nullopt: the device stays silent (not addressed; a short frame
    // with a command other than 0; an ACK/BACK frame of another device).
    std::optional<hart::Frame> handle(const hart::Frame &request);

    // Power cycle: cold start flags set, configuration kept (it is in non-volatile memory).
    void powerCycle();

    hart::Identity identity() const;
    hart::Address address() const; // long frame address of this device
    std::uint8_t pollAddress() const { return m_pollAddress; }
    const std::string &tag() const { return m_tag; }
    const std::string &longTag() const { return m_longTag; }
    const std::string &descriptor() const { return m_descriptor; }
    const std::string &message() const { return m_message; }
    const hart::Date &date() const { return m_date; }
    std::uint32_t finalAssemblyNumber() const { return m_finalAssembly; }
    std::uint16_t configChangeCounter() const { return m_configCounter; }
    bool configChanged(bool primaryMaster) const
    {
        return m_configChanged[masterIndex(primaryMaster)];
    }
    // Status byte 2 the next response to that master would carry.
    std::uint8_t deviceStatus(bool primaryMaster) const;

    Dsp408ParamStore &params() { return m_params; }
    const Dsp408ParamStore &params() const { return m_params; }
    Dsp408Drive &drive() { return m_drive; }

    // What commands 17, 18, 19 and 22 write (HART-7 manual §5.1), as the device holds it: kept
    // in non-volatile memory, so a bench device still has it at the next connection.
    struct Texts
    {
        std::string tag, longTag, descriptor, message;
        hart::Date date;
        std::uint32_t finalAssemblyNumber = 0;
    };
    Texts texts() const
    {
        return {m_tag, m_longTag, m_descriptor, m_message, m_date, m_finalAssembly};
    }
    void setTexts(const Texts &texts)
    {
        m_tag = texts.tag;
        m_longTag = texts.longTag;
        m_descriptor = texts.descriptor;
        m_message = texts.message;
        m_date = texts.date;
        m_finalAssembly = texts.finalAssemblyNumber;
    }

    // Analog input 3: the 4..20 mA loop current the HART signal rides on (HART-7 manual §3.2).
    void setLoopCurrent(float mA) { m_loopCurrentMa = mA; }
    // Fault injection: error present → FAULT, "device malfunction" and "more status available".
    void injectError(std::uint16_t code);
    void clearError();

    void step(const SimStep &step) override;

private:
    struct Reply
    {
        std::uint8_t code = hart_rc::kOk;
        Bytes data;
        bool silent = false;
    };

    static std::size_t masterIndex(bool primaryMaster) { return primaryMaster ? 0 : 1; }
    bool addressed(const hart::Address &address, std::uint8_t command) const;
    Reply dispatch(const hart::Frame &request);
    Reply universal(std::uint8_t command, const hart::Payload &payload, bool primaryMaster);
    Reply parameter(std::uint8_t command, const Bytes &data);
    Reply writeParameter(const ParamMeta &meta, double raw);
    std::uint8_t refusal(ParamErrc error) const;
    void configurationChanged();

    // Process values of commands 1, 2, 3, 9 (plausible device values, see the doc).
    float percentOfRange() const;
    float primaryValue() const;
    hart::DynamicVariables dynamicVariables() const;
    Reply deviceVariables(const hart::DeviceVariableCodes &codes) const;
    hart::AdditionalStatus additionalStatus() const;

    Options m_options;
    Dsp408ParamStore m_params;
    Dsp408Drive m_drive;
    std::uint8_t m_pollAddress = 0;
    std::uint8_t m_loopCurrentMode = 1;
    std::string m_tag, m_longTag, m_descriptor, m_message;
    hart::Date m_date;
    std::uint32_t m_finalAssembly = 0;
    std::uint16_t m_configCounter = 0;
    std::array<bool, 2> m_configChanged{};
    std::array<bool, 2> m_coldStart{true, true};
    std::uint16_t m_errorCode = 0;
    float m_loopCurrentMa = 4.0f;
    std::int64_t m_timeUs = 0;
};

} // namespace vt::dev::sim
