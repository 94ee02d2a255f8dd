// CMD 15 layouts per software version and mode: what VALUE1/VALUE2 mean and which control / status
// bits the version uses (OPAT manual §3.5, DMA Profinet manual §4.5, DMA Profibus Anleitung §4.5).
#pragma once

#include "core/local_text.h"
#include "types.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace vt::dev::hcs {

enum class Profile : std::uint8_t {
    DmaV13Mode1,   // DMA Profinet manual §4.5.2: open loop, one valve with two solenoids
    DmaV15Mode1,   // DMA Profibus Anleitung §4.5.2: the same layout on Profibus
    DmaV22Mode2,   // DMA Profibus Anleitung §4.5.3: open loop, two valves with one solenoid each
    DmaV32Mode34,  // DMA Profibus Anleitung §4.5.4: closed loop, modes 3/4 (also V31)
    DmaV32Mode6,   // DMA Profibus Anleitung §4.5.5
    DmaV32Mode8,   // DMA Profibus Anleitung §4.5.6
    DmaV51Mode34,  // DMA Profinet manual §4.5.3: closed loop, modes 3/4
    OpatV34Mode34, // OPAT manual §3.5.2: V34 master / V31 CAN slave, closed loop, modes 3/4
    OpatV34Mode6,  // OPAT manual §3.5.3
    OpatV34Mode8,  // OPAT manual §3.5.4
};

enum class ValueUnit : std::uint8_t {
    Millivolt,   // "1000 == 1.000 V"
    Milliampere, // d1.07 / d1.08: "1000 == 1.000 A"
};

struct ValueMeaning
{
    std::string_view parameter; // "A1.01", "d1.11"
    LocalText text;             // "set value input (bus) (branch 1)"
    ValueUnit unit = ValueUnit::Millivolt;
};

struct ProfileInfo
{
    Profile profile;
    Family family;
    std::string_view key;       // "dma-v32-mode6": stable name for options and the CLI
    LocalText title;            // "DMA V32, mode 6 (closed loop)"
    std::string_view source;    // manual and section
    ValueMeaning request1;      // DATx.2 of the request
    ValueMeaning request2;      // DATx.3 of the request
    ValueMeaning response1;     // DAT.2 (VALUE1) of the response
    ValueMeaning response2;     // DAT.3 (VALUE2) of the response
    std::uint8_t controlBits;   // control-byte bits the version uses; the others are reserved
    std::uint8_t statusLowBits; // status low-byte signal bits the version reports
};

const ProfileInfo &profileInfo(Profile profile);
std::span<const ProfileInfo> allProfiles();

// What describe() assumes when no version/mode is given: the layout of the family's worked
// examples — OPAT V34 modes 3/4 (OPAT manual §3.4), DMA V13/V15 mode 1 (DMA manuals §4.4).
Profile defaultProfile(Family family);

// Software major version (13, 15, 22, 31, 32, 34, 51) and mode (E00); 0 = "not known", which
// picks the family default / the version's first mode. nullopt when the manuals define no
// CMD 15 layout for the combination.
std::optional<Profile> profileFor(Family family, int version, int mode);
std::optional<Profile> profileByKey(std::string_view key);

} // namespace vt::dev::hcs
