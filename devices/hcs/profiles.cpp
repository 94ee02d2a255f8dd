#include "profiles.h"

#include <array>

namespace vt::dev::hcs {
namespace {

// German wording from the DMA Profibus Anleitung §4.5.2–4.5.6 ("Sollwert Eingang (Profibus) für
// (Zweig 1)", "Aktueller Istwert (Zweig 1)", …) with "Profibus" generalised to "Bus".
const ValueMeaning kA101{
    "A1.01", {"set value input (bus)", "Sollwert Eingang (Bus)"}, ValueUnit::Millivolt};
const ValueMeaning kA101Branch1{
    "A1.01",
    {"set value input (bus) for branch 1", "Sollwert Eingang (Bus) für Zweig 1"},
    ValueUnit::Millivolt};
// DMA Profibus Anleitung R2.9: "Korrigiertes Beispiel für SW15.xx (modus1) (A1.02 wurde A2.01)";
// the DMA Profinet manual §4.5.2 still prints "A1.01 … (normally not used)".
const ValueMeaning kA201Unused{
    "A2.01",
    {"set value input (bus), normally not used", "Sollwert Eingang (Bus), normal nicht benötigt"},
    ValueUnit::Millivolt};
const ValueMeaning kA201Branch2{
    "A2.01",
    {"set value input (bus) for branch 2", "Sollwert Eingang (Bus) für Zweig 2"},
    ValueUnit::Millivolt};
const ValueMeaning kA102Branch1{
    "A1.02",
    {"feedback value input (bus) for branch 1", "Istwert Eingang (Bus) für Zweig 1"},
    ValueUnit::Millivolt};
const ValueMeaning kA202Branch2{
    "A2.02",
    {"feedback value input (bus) for branch 2", "Istwert Eingang (Bus) für Zweig 2"},
    ValueUnit::Millivolt};
const ValueMeaning kD107{
    "d1.07", {"actual current A", "Aktueller Strom A"}, ValueUnit::Milliampere};
const ValueMeaning kD108{
    "d1.08", {"actual current B", "Aktueller Strom B"}, ValueUnit::Milliampere};
const ValueMeaning kD111{"d1.11",
                         {"actual value, feedback value (branch 1)", "Aktueller Istwert (Zweig 1)"},
                         ValueUnit::Millivolt};
const ValueMeaning kD110{
    "d1.10",
    {"set value (internal value) (branch 1)", "Sollwert (interner Wert) (Zweig 1)"},
    ValueUnit::Millivolt};
const ValueMeaning kD211{"d2.11",
                         {"actual value, feedback value (branch 2)", "Aktueller Istwert (Zweig 2)"},
                         ValueUnit::Millivolt};

// Control bits: 0x80 BUS_DISABLE always; closed-loop versions add 0x01 Din_1, 0x04 TST_CMP and
// (except V51) 0x10 Din_2. Status low byte: open-loop versions report nothing ("always zero").
constexpr std::uint8_t kCtlOpen = 0x80;
constexpr std::uint8_t kCtlClosed = 0x95;
constexpr std::uint8_t kCtlV51 = 0x85;

const std::array<ProfileInfo, 10> kProfiles{{
    {Profile::DmaV13Mode1,
     Family::Dma,
     "dma-v13-mode1",
     {"DMA V13, mode 1 (open loop, one valve with two solenoids)",
      "DMA V13, Modus 1 (gesteuert, ein Ventil mit zwei Magneten)"},
     "DMA Profinet manual §4.5.2",
     kA101,
     kA201Unused,
     kD107,
     kD108,
     kCtlOpen,
     0x00},
    {Profile::DmaV15Mode1,
     Family::Dma,
     "dma-v15-mode1",
     {"DMA V15, mode 1 (open loop, one valve with two solenoids)",
      "DMA V15, Modus 1 (gesteuert, ein Ventil mit zwei Magneten)"},
     "DMA Profibus Anleitung §4.5.2",
     kA101,
     kA201Unused,
     kD107,
     kD108,
     kCtlOpen,
     0x00},
    {Profile::DmaV22Mode2,
     Family::Dma,
     "dma-v22-mode2",
     {"DMA V22, mode 2 (open loop, two valves with one solenoid each)",
      "DMA V22, Modus 2 (gesteuert, zwei Ventile mit jeweils einem Magnet)"},
     "DMA Profibus Anleitung §4.5.3",
     kA101Branch1,
     kA201Branch2,
     kD107,
     kD108,
     kCtlOpen,
     0x00},
    {Profile::DmaV32Mode34,
     Family::Dma,
     "dma-v32-mode34",
     {"DMA V32, modes 3/4 (closed loop)", "DMA V32, Modus 3/4 (geregelt)"},
     "DMA Profibus Anleitung §4.5.4",
     kA101Branch1,
     kA102Branch1,
     kD111,
     kD110,
     kCtlClosed,
     0xFF},
    {Profile::DmaV32Mode6,
     Family::Dma,
     "dma-v32-mode6",
     {"DMA V32, mode 6 (closed loop)", "DMA V32, Modus 6 (geregelt)"},
     "DMA Profibus Anleitung §4.5.5",
     kA101Branch1,
     kA202Branch2,
     kD111,
     kD211,
     kCtlClosed,
     0xFF},
    {Profile::DmaV32Mode8,
     Family::Dma,
     "dma-v32-mode8",
     {"DMA V32, mode 8 (closed loop)", "DMA V32, Modus 8 (geregelt)"},
     "DMA Profibus Anleitung §4.5.6",
     kA101Branch1,
     kA201Branch2,
     kD111,
     kD211,
     kCtlClosed,
     0xFF},
    {Profile::DmaV51Mode34,
     Family::Dma,
     "dma-v51-mode34",
     {"DMA V51, modes 3/4 (closed loop)", "DMA V51, Modus 3/4 (geregelt)"},
     "DMA Profinet manual §4.5.3",
     kA101Branch1,
     kA102Branch1,
     kD111,
     kD110,
     kCtlV51,
     0x0F},
    {Profile::OpatV34Mode34,
     Family::Opat,
     "opat-v34-mode34",
     {"OPAT V34/V31, modes 3/4 (closed loop)", "OPAT V34/V31, Modus 3/4 (geregelt)"},
     "OPAT manual §3.5.2",
     kA101Branch1,
     kA102Branch1,
     kD111,
     kD110,
     kCtlClosed,
     0xFF},
    {Profile::OpatV34Mode6,
     Family::Opat,
     "opat-v34-mode6",
     {"OPAT V34/V31, mode 6 (closed loop)", "OPAT V34/V31, Modus 6 (geregelt)"},
     "OPAT manual §3.5.3",
     kA101Branch1,
     kA202Branch2,
     kD111,
     kD211,
     kCtlClosed,
     0xFF},
    {Profile::OpatV34Mode8,
     Family::Opat,
     "opat-v34-mode8",
     {"OPAT V34/V31, mode 8 (closed loop)", "OPAT V34/V31, Modus 8 (geregelt)"},
     "OPAT manual §3.5.4",
     kA101Branch1,
     kA201Branch2,
     kD111,
     kD211,
     kCtlClosed,
     0xFF},
}};

std::optional<Profile> closedLoop(int mode, Profile m34, Profile m6, Profile m8)
{
    switch (mode) {
    case 0:
    case 3:
    case 4: return m34;
    case 6: return m6;
    case 8: return m8;
    default: return std::nullopt;
    }
}

} // namespace

const ProfileInfo &profileInfo(Profile profile)
{
    for (const ProfileInfo &info : kProfiles)
        if (info.profile == profile)
            return info;
    return kProfiles.front(); // unreachable for a valid enum value
}

std::span<const ProfileInfo> allProfiles()
{
    return kProfiles;
}

Profile defaultProfile(Family family)
{
    return family == Family::Opat ? Profile::OpatV34Mode34 : Profile::DmaV15Mode1;
}

std::optional<Profile> profileFor(Family family, int version, int mode)
{
    if (family == Family::Opat) {
        // OPAT manual §1.2: V34 = Profibus master, V31 = CAN slave; both share §3.5's layouts.
        if (version != 0 && version != 34 && version != 31)
            return std::nullopt;
        return closedLoop(mode, Profile::OpatV34Mode34, Profile::OpatV34Mode6,
                          Profile::OpatV34Mode8);
    }
    switch (version) {
    case 0:
        if (mode == 0 || mode == 1)
            return Profile::DmaV15Mode1;
        if (mode == 2)
            return Profile::DmaV22Mode2;
        return closedLoop(mode, Profile::DmaV32Mode34, Profile::DmaV32Mode6, Profile::DmaV32Mode8);
    case 13: return mode == 0 || mode == 1 ? std::optional(Profile::DmaV13Mode1) : std::nullopt;
    case 15: return mode == 0 || mode == 1 ? std::optional(Profile::DmaV15Mode1) : std::nullopt;
    case 22: return mode == 0 || mode == 2 ? std::optional(Profile::DmaV22Mode2) : std::nullopt;
    case 31: // DMA Profibus Anleitung §1.2 / R1.6: V31 shares the V32 parameter and telegram set
    case 32:
        return closedLoop(mode, Profile::DmaV32Mode34, Profile::DmaV32Mode6, Profile::DmaV32Mode8);
    case 51:
        return mode == 0 || mode == 3 || mode == 4 ? std::optional(Profile::DmaV51Mode34)
                                                   : std::nullopt;
    default: return std::nullopt;
    }
}

std::optional<Profile> profileByKey(std::string_view key)
{
    for (const ProfileInfo &info : kProfiles)
        if (info.key == key)
            return info.profile;
    return std::nullopt;
}

} // namespace vt::dev::hcs
