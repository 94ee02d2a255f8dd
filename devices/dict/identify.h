// Identification: which dictionary describes a module, from what the module reports — HCS:
// `Vers` (ID 0, raw = version × 100, "34.03" = 3403) and `E00` (mode); Wandfluh: the DSP-408
// capability (db_Capability) or HART command 0. An unknown version falls back to the nearest
// family with a warning, never silently.
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "dictionary.h"

#include <cstdint>
#include <string>

namespace vt::dev {

// What the connection already tells about the product (the user picked it, or the link implies
// it): needed because version numbers overlap (V31 = OPAT CAN slave and DMA PROFIBUS V31).
enum class HcsProduct { Unknown, Opat, DmaProfinet, DmaProfibus };

struct Identification
{
    std::string family;  // dictionary family id
    std::string version; // "34.03", "SD7 device type 58352"
    std::string mode;    // "3"; empty when not applicable
    bool exact = true;   // false: fallback, see warning
    LocalText warning;
};

Result<Identification, LocalText> identifyHcs(const DictionarySet &set, int versRaw, int e00,
                                              HcsProduct product);

// ED1/SD1 manual §4.8.7: 0x00130000 = hydraulic drive, open loop movement and position control.
// `capability` 0: not reported (CANopen device type 408 without a capability object) — the
// manual's value is named, with a warning.
Result<Identification, LocalText> identifyDsp408(const DictionarySet &set,
                                                 std::uint32_t capability);

// HART manual §4.4 / §5.1 command 0: manufacturer 24835 (0x6103) = Wandfluh; SD733 = 58352,
// SD736 = 58353 (SD730 and SD735 "tbd" in the manual).
Result<Identification, LocalText> identifyHart(const DictionarySet &set, std::uint16_t manufacturer,
                                               std::uint16_t expandedDeviceType);

inline constexpr std::uint16_t kWandfluhHartManufacturer = 24835;

// A version as identifyDsp408 / identifyHart write it ("capability 0x00130000", "device type
// 58352"), in both languages for people; the string itself stays the key that files and
// dictionaries compare. Any other version (HCS "51.02") is the same in both.
LocalText versionText(const std::string &version);

} // namespace vt::dev
