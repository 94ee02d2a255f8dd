// ParamMeta: immutable metadata of one parameter (type, raw range, scale, unit, enum labels,
// access, block, texts), loaded from a device dictionary (docs/DICTIONARY.md). Values live
// elsewhere (STYLE.md rule 4). Shared read-only between threads once loaded.
#pragma once

#include "core/enum_key.h"
#include "core/local_text.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev {

enum class Access {
    Read,           // r: read only
    ReadWrite,      // rw
    Write,          // w: write only (commands)
    Inactive,       // x: "implemented, but not active (no access)"
    NotImplemented, // n: grey in the manual, "not yet implemented"
};

// What a row is to a parameter file (ARCHITECTURE.md "Trust rules"; the rule per family is in
// docs/DICTIONARY.md "Row kinds"): a setting is kept on the device and belongs in a file; a
// process value is written by the PLC or a test at run time; a live value is read-only status.
enum class RowKind { Setting, Process, Live };

inline constexpr std::array kRowKinds{RowKind::Setting, RowKind::Process, RowKind::Live};

// "setting", "process", "live" (the dictionaries' "row_kind" field).
const char *key(RowKind kind);
template<> std::optional<RowKind> fromKey<RowKind>(std::string_view key);

enum class RawType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, String };

enum class Persistence { Unspecified, Eeprom, Volatile };

enum class Rounding { Nearest, Truncate };

struct Scale
{
    std::string name;    // empty: raw value shown as is
    double factor = 1.0; // display = raw × factor
    int decimals = 0;
    Rounding rounding = Rounding::Nearest;
    bool assumed = false; // depends on the installation; the factor is a typical value
    std::string note;
};

struct EnumLabel
{
    std::int64_t value = 0;
    LocalText text;
};

struct BitLabel
{
    int bit = 0;
    LocalText text;
};

struct CanObject
{
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
};

struct ParamMeta
{
    std::string name;
    std::optional<int> id;       // HCS parameter ID
    std::optional<int> ind, pnu; // Wandfluh index / parameter number
    int instance = 0;            // HART instance
    std::optional<int> pzd;      // DSP-408 process data number
    std::string block;           // d C E A L r S B system, or the Wandfluh function block
    int branch = 0;              // 1 or 2 for HCS branch rows, else 0
    Access access = Access::Read;
    RowKind kind = RowKind::Setting;
    bool movesActuator = false; // writing it can move the actuator: set values, the set-value
                                // source (E17 and its equivalents), enable/control words
    RawType type = RawType::Int16;
    int length = 0; // strings: bytes on the wire
    double min = 0, max = 0, step = 1;
    std::string minParam, maxParam;
    std::optional<double> defaultValue;
    bool defaultAssumed = false;
    std::string unit;
    Scale scale;
    std::vector<EnumLabel> enums;
    std::vector<BitLabel> bits;
    std::vector<std::string> modes;    // empty: all modes of the family
    std::vector<std::string> versions; // empty: all versions of the family
    Persistence persistence = Persistence::Unspecified;
    std::optional<CanObject> canopen;
    LocalText label;
    LocalText description;
    std::string note; // transcription note, not shown to users

    bool readable() const { return access == Access::Read || access == Access::ReadWrite; }
    bool writable() const { return access == Access::ReadWrite || access == Access::Write; }
    bool isString() const { return type == RawType::String; }
    bool isFloat() const { return type == RawType::Float32; }
    const EnumLabel *findEnum(std::int64_t value) const;
    bool appliesTo(const std::string &version, const std::string &mode) const;
    // "ID 0x30", "IND 3 / PNU 129", "IND 11 / PNU 46 / inst 0"
    std::string addressText() const;
};

// Representable raw range of a type (float: ±FLT_MAX; string: 0..0).
double typeMin(RawType type);
double typeMax(RawType type);
// Bytes the type occupies on a fieldbus (ED1/SD1 manual §4.6 "data type / parameter length",
// HART-7 manual §4.4.1, CANopen expedited SDO): 1, 2 or 4; 0 for strings.
std::size_t wireBytes(RawType type);

const char *accessKey(Access access); // "r", "rw", "w", "x", "n"
const char *rawTypeKey(RawType type); // "int16", …
std::optional<Access> parseAccess(const std::string &key);
std::optional<RawType> parseRawType(const std::string &key);
LocalText accessText(Access access);

} // namespace vt::dev
