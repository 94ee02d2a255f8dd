// Parameter values of a simulated Wandfluh device by IND / PNU / instance, filled with the
// dictionary's defaults, with the checks a device makes before it takes a written value (access,
// raw range narrowed by min_param / max_param). Shared by the ED1/SD1 (DSP-408, PKW) and the SD7
// (HART, commands 128..133) simulators: both manuals use the same profile rows (HART-7 manual
// §5.2 IND 0 = ED1/SD1 manual §4.4 db block) and the same "one value per IND/PNU" model.
// Owner: the simulated device; single-threaded. The Dictionary must outlive the store.
#pragma once

#include "dict/cooking.h"
#include "dict/dictionary.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace vt::dev::sim {

// Why a device refuses a parameter access. Each front end maps these to its protocol's codes
// (PKW error number, HART response code, CiA 301 abort code).
enum class ParamErrc {
    Unknown,      // no such IND/PNU/instance (or a row the device does not implement: access n, x)
    NotReadable,  // write-only row (commands such as db_ControlWord, db_ResetDefault)
    ReadOnly,     // read-only row
    BelowMin,     // below the row's minimum (or the min_param row's value)
    AboveMax,     // above the row's maximum (or the max_param row's value)
    WrongWidth,   // the request's value width is not the row's type width
    InvalidValue, // in range, but not a value the row accepts (e.g. db_ResetDefault not 'load')
    WrongState, // not changeable in the present device state (§4.2.2: modes only in INIT/DISABLED)
};

class Dsp408ParamStore
{
public:
    explicit Dsp408ParamStore(const Dictionary &dictionary);

    const Dictionary &dictionary() const { return *m_dict; }

    // The row the device implements at IND/PNU/instance; nullptr for unknown rows, rows with
    // access n or x, and string rows (no PKW/HART parameter command carries them).
    const ParamMeta *find(int ind, int pnu, int instance = 0) const;
    const ParamMeta *find(std::string_view name) const;

    // Stored raw value. No access checks: the device itself reads and writes live rows.
    double value(const ParamMeta &meta) const;
    double value(std::string_view name, double fallback = 0) const;
    void set(const ParamMeta &meta, double raw);
    bool set(std::string_view name, double raw);

    // The row's raw limits narrowed by the current values of its min_param / max_param rows
    // (ED1/SD1 manual §4.8.18: "0 … dop_drivePos_AsideMaxVal").
    Limits limits(const ParamMeta &meta) const;
    // What a master's write must pass: writable, value representable and within limits.
    std::optional<ParamErrc> checkWrite(const ParamMeta &meta, double raw) const;

    // Every row back to its default (db_ResetDefault 'load').
    void resetDefaults();
    static double defaultOf(const ParamMeta &meta);

    // Rows in dictionary order with their values, e.g. to save or compare images.
    std::size_t size() const { return m_values.size(); }

private:
    std::size_t indexOf(const ParamMeta &meta) const;

    const Dictionary *m_dict;
    std::vector<double> m_values; // parallel to m_dict->params
};

// ED1/SD1 manual §4.8.8 / §4.8.9 (SD7: HART-7 manual §5.2 IND 0 PNU 52): the command words.
inline constexpr std::uint32_t kStoreParameterSave = 0x73617665; // 's' 'a' 'v' 'e'
inline constexpr std::uint32_t kResetDefaultLoad = 0x6C6F6164;   // 'l' 'o' 'a' 'd'

// db_DeviceMode, db_ControlMode, db_Local: the device configuration that may change only in
// INIT or DISABLED (ED1/SD1 manual §4.2.2 state table, HART-7 manual §4.2.1).
bool isModeRow(const ParamMeta &meta);

// Raw value → the zero-extended wire bits (two's complement for signed types, IEEE 754 bits for
// float32), and back: the low `wireBytes` bytes sign-extended by the row's type.
std::uint32_t toWireBits(const ParamMeta &meta, double raw);
double fromWireBits(const ParamMeta &meta, std::uint32_t bits);

} // namespace vt::dev::sim
