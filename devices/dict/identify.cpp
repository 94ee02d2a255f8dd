#include "identify.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string_view>

namespace vt::dev {
namespace {

// The version strings identifyDsp408 and identifyHart write (versionText reads them back).
constexpr const char *kCapability = "capability ";
constexpr const char *kNotReported = " (manual; not reported)";
constexpr const char *kDeviceType = "device type ";

bool productMatches(const Dictionary &d, HcsProduct product)
{
    switch (product) {
    case HcsProduct::Unknown: return true;
    case HcsProduct::Opat: return d.family.rfind("opat", 0) == 0;
    case HcsProduct::DmaProfinet: return d.family.rfind("dma-pn-", 0) == 0;
    case HcsProduct::DmaProfibus: return d.family.rfind("dma-pb-", 0) == 0;
    }
    return false;
}

bool contains(const std::vector<std::string> &list, const std::string &v)
{
    return std::find(list.begin(), list.end(), v) != list.end();
}

} // namespace

Result<Identification, LocalText> identifyHcs(const DictionarySet &set, int versRaw, int e00,
                                              HcsProduct product)
{
    if (versRaw <= 0 || versRaw > 9999)
        return LocalText{
            "the module reports no valid software version (Vers = " + std::to_string(versRaw) + ")",
            "das Modul meldet keine gültige Softwareversion (Vers = " + std::to_string(versRaw) +
                ")"};
    const int major = versRaw / 100;
    char versionText[16];
    std::snprintf(versionText, sizeof versionText, "%d.%02d", major, versRaw % 100);
    const std::string majorText = std::to_string(major);
    const std::string mode = std::to_string(e00);

    const Dictionary *best = nullptr;
    int bestScore = std::numeric_limits<int>::max();
    bool exact = false;
    for (const std::string &family : set.families()) {
        const Dictionary *d = set.find(family);
        if (!d || d->protocol != DeviceProtocol::Hcs || !productMatches(*d, product))
            continue;
        const bool modeOk = d->modes.empty() || contains(d->modes, mode);
        if (contains(d->versions, majorText) && modeOk) {
            best = d;
            exact = true;
            break;
        }
        // Fallback distance: version numbers apart, a mode mismatch counts as far.
        for (const std::string &v : d->versions) {
            const int score = std::abs(std::atoi(v.c_str()) - major) + (modeOk ? 0 : 1000);
            if (score < bestScore) {
                bestScore = score;
                best = d;
            }
        }
    }
    if (!best)
        return LocalText{"no HCS dictionary fits this module",
                         "kein HCS-Wörterbuch passt zu diesem Modul"};
    Identification id{best->family, versionText, mode, exact, {}};
    if (!exact)
        id.warning = {"unknown software version V" + std::string(versionText) + " in mode " + mode +
                          "; using the nearest dictionary " + best->family + " — check every value",
                      "unbekannte Softwareversion V" + std::string(versionText) + " in Modus " +
                          mode + "; verwendet wird das nächstliegende Wörterbuch " + best->family +
                          " — alle Werte prüfen"};
    return id;
}

LocalText versionText(const std::string &version)
{
    const auto starts = [&](std::string_view prefix) { return version.starts_with(prefix); };
    if (starts(kCapability)) {
        std::string rest = version.substr(std::string_view(kCapability).size());
        std::string de = "Fähigkeiten " + rest;
        if (rest.ends_with(kNotReported))
            de = "Fähigkeiten " +
                 rest.substr(0, rest.size() - std::string_view(kNotReported).size()) +
                 " (Handbuch; nicht gemeldet)";
        return {version, de};
    }
    if (starts(kDeviceType))
        return {version, "Gerätetyp " + version.substr(std::string_view(kDeviceType).size())};
    return same(version);
}

Result<Identification, LocalText> identifyDsp408(const DictionarySet &set, std::uint32_t capability)
{
    if (!set.find("wandfluh-ed1"))
        return LocalText{"the ED1/SD1 dictionary is missing", "das ED1/SD1-Wörterbuch fehlt"};
    Identification id{"wandfluh-ed1", {}, {}, true, {}};
    if (capability == 0) {
        // CANopen without a capability object: device type 408 (CiA 301 0x1000) alone.
        id.version = std::string(kCapability) + "0x00130000" + kNotReported;
        id.exact = false;
        id.warning = {"the device reports profile 408 but no capability; using wandfluh-ed1, "
                      "whose manual gives 0x00130000 (hydraulic drive, open loop movement and "
                      "position control)",
                      "das Gerät meldet Profil 408, aber keine Fähigkeiten; verwendet wird "
                      "wandfluh-ed1, dessen Handbuch 0x00130000 nennt (hydraulischer Antrieb, "
                      "gesteuerter Betrieb und Lageregelung)"};
        return id;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08X", capability);
    id.version = std::string(kCapability) + hex;
    if (capability != 0x00130000u) {
        id.exact = false;
        id.warning = {
            std::string("capability ") + hex +
                " differs from the ED1/SD1 manual's 0x00130000; using wandfluh-ed1",
            std::string("Fähigkeiten ") + hex +
                " weichen vom ED1/SD1-Handbuch (0x00130000) ab; verwendet wird wandfluh-ed1"};
    }
    return id;
}

Result<Identification, LocalText> identifyHart(const DictionarySet &set, std::uint16_t manufacturer,
                                               std::uint16_t expandedDeviceType)
{
    if (manufacturer != kWandfluhHartManufacturer)
        return LocalText{
            "HART manufacturer " + std::to_string(manufacturer) + " is not Wandfluh (24835)",
            "HART-Hersteller " + std::to_string(manufacturer) + " ist nicht Wandfluh (24835)"};
    if (!set.find("wandfluh-sd7"))
        return LocalText{"the SD7 dictionary is missing", "das SD7-Wörterbuch fehlt"};
    Identification id{
        "wandfluh-sd7", kDeviceType + std::to_string(expandedDeviceType), {}, true, {}};
    if (expandedDeviceType != 58352 && expandedDeviceType != 58353) {
        id.exact = false;
        id.warning = {
            "Wandfluh HART device type " + std::to_string(expandedDeviceType) +
                " is not in the HART manual (SD733 58352, SD736 58353); using wandfluh-sd7",
            "Wandfluh-HART-Gerätetyp " + std::to_string(expandedDeviceType) +
                " steht nicht im HART-Handbuch (SD733 58352, SD736 58353); verwendet wird "
                "wandfluh-sd7"};
    }
    return id;
}

} // namespace vt::dev
