#include "param_file_map.h"

#include "core/version.h"
#include "dict/cooking.h"
#include "file_rows.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace vt::dev::files {
namespace {

bool contains(const std::vector<std::string> &list, const std::string &v)
{
    return std::find(list.begin(), list.end(), v) != list.end();
}

std::string joined(const std::vector<std::string> &list)
{
    std::string out;
    for (const std::string &s : list)
        out += (out.empty() ? "" : ", ") + s;
    return out;
}

std::string addressOf(const ParamMeta &meta)
{
    return meta.addressText().empty() ? meta.name : meta.addressText();
}

LocalText notApplicable(const ParamMeta &meta, const std::string &major, const std::string &mode)
{
    if (!meta.versions.empty() && !major.empty() && !contains(meta.versions, major))
        return {meta.name + " exists only in software version " + joined(meta.versions) +
                    ", not in V" + major,
                meta.name + " gibt es nur in Softwareversion " + joined(meta.versions) +
                    ", nicht in V" + major};
    return {meta.name + " applies only in mode " + joined(meta.modes) + ", not in mode " + mode,
            meta.name + " gilt nur in Modus " + joined(meta.modes) + ", nicht in Modus " + mode};
}

RowMapping classify(const ValueRow &row, const ParamMeta &meta, bool byAddress,
                    const std::string &family, const std::string &major, const std::string &mode)
{
    RowMapping out{MapStatus::Mapped, 0, row.name, &meta, {}, false};
    if (!meta.appliesTo(major, mode)) {
        out.status = MapStatus::NotApplicable;
        out.reason = notApplicable(meta, major, mode);
        return out;
    }
    if (meta.isString() != isText(row.raw)) {
        out.status = MapStatus::TypeMismatch;
        out.reason = meta.isString()
                         ? LocalText{meta.name + " holds a text; the file has a number",
                                     meta.name + " enthält einen Text; die Datei hat eine Zahl"}
                         : LocalText{meta.name + " holds a number; the file has a text",
                                     meta.name + " enthält eine Zahl; die Datei hat einen Text"};
        return out;
    }
    if (meta.isString()) {
        const std::size_t size = std::get<std::string>(row.raw).size();
        if (meta.length > 0 && size > static_cast<std::size_t>(meta.length)) {
            out.status = MapStatus::OutOfRange;
            out.reason = {meta.name + ": the text has " + std::to_string(size) +
                              " bytes, the row holds " + std::to_string(meta.length),
                          meta.name + ": der Text hat " + std::to_string(size) +
                              " Bytes, die Zeile fasst " + std::to_string(meta.length)};
            return out;
        }
    } else {
        const double v = rawNumber(row.raw);
        if (!meta.isFloat() && std::isfinite(v) && v != std::floor(v)) {
            out.status = MapStatus::TypeMismatch;
            out.reason = {meta.name + " takes whole numbers; the file has " + rawNumberText(v),
                          meta.name + " nimmt nur ganze Zahlen; die Datei hat " + rawNumberText(v)};
            return out;
        }
        // Only values that can be written are range-checked: a read-only row (a live display
        // value, a HART NaN "not available") and a process value are never sent back.
        if (meta.writable() && isFileRow(meta)) {
            if (auto err = checkRange(meta, v)) {
                out.status = MapStatus::OutOfRange;
                out.reason = err->message;
                return out;
            }
        }
    }
    if (byAddress) {
        out.status = MapStatus::MappedByAddress;
        out.reason = {row.name + " is named " + meta.name + " in " + family + " (same " +
                          addressOf(meta) + ")",
                      row.name + " heißt in " + family + " " + meta.name + " (gleiche " +
                          addressOf(meta) + ")"};
    }
    return out;
}

void moduleNotes(MapReport &report, const ModuleRecord &record, const Dictionary &dict,
                 const MapTarget &t, const std::string &major, bool explicitTarget)
{
    if (record.family != dict.family)
        report.notes.push_back({"the file was written for " + record.family +
                                    "; its values are mapped onto " + dict.family,
                                "die Datei wurde für " + record.family +
                                    " geschrieben; ihre Werte werden auf " + dict.family +
                                    " abgebildet"});
    if (explicitTarget && (majorVersion(record.version) != major || record.mode != t.mode))
        report.notes.push_back(
            {"the file was saved from version " + record.version + " in mode " + record.mode +
                 "; this module runs " + t.version + " in mode " + t.mode,
             "die Datei stammt von Version " + record.version + " in Modus " + record.mode +
                 "; dieses Modul hat " + t.version + " in Modus " + t.mode});
    if (!major.empty() && !dict.versions.empty() && !contains(dict.versions, major))
        report.notes.push_back({dict.family + " describes software version " +
                                    joined(dict.versions) + ", not V" + major,
                                dict.family + " beschreibt Softwareversion " +
                                    joined(dict.versions) + ", nicht V" + major});
    if (!t.mode.empty() && !dict.modes.empty() && !contains(dict.modes, t.mode))
        report.notes.push_back(
            {dict.family + " describes mode " + joined(dict.modes) + ", not mode " + t.mode,
             dict.family + " beschreibt Modus " + joined(dict.modes) + ", nicht Modus " + t.mode});
}

// One note per kind, naming the rows, so an old file that saved set values or display values
// says that they stay out of every write.
void ignoredNotes(MapReport &report)
{
    std::vector<std::string> process, live;
    for (RowMapping &m : report.rows) {
        if (!m.meta || isFileRow(*m.meta))
            continue;
        m.ignoredForWriting = true;
        (m.meta->kind == RowKind::Process ? process : live).push_back(m.name);
    }
    if (!process.empty())
        report.notes.push_back(
            {"process values, not settings, kept in the file and ignored for writing: " +
                 joined(process),
             "Prozesswerte, keine Einstellungen, bleiben in der Datei und werden nicht "
             "geschrieben: " +
                 joined(process)});
    if (!live.empty())
        report.notes.push_back(
            {"live values, not settings, kept in the file and ignored for writing: " + joined(live),
             "Live-Werte, keine Einstellungen, bleiben in der Datei und werden nicht "
             "geschrieben: " +
                 joined(live)});
}

} // namespace

const ParamMeta *findMeta(const Dictionary &dict, const ValueRow &row, bool *byAddress)
{
    if (byAddress)
        *byAddress = false;
    if (const ParamMeta *p = dict.find(row.name))
        return p;
    const ParamMeta *p = nullptr;
    if (row.id)
        p = dict.findId(*row.id);
    if (!p && row.ind && row.pnu)
        p = dict.findIndPnu(*row.ind, *row.pnu, row.instance.value_or(0));
    if (p && byAddress)
        *byAddress = true;
    return p;
}

MapReport mapModule(const ModuleRecord &record, const Dictionary &dict,
                    const std::optional<MapTarget> &target)
{
    MapReport report;
    report.family = dict.family;
    const MapTarget t = target.value_or(MapTarget{record.version, record.mode});
    const std::string major = majorVersion(t.version);
    moduleNotes(report, record, dict, t, major, target.has_value());

    // Names first, so that an address fallback never takes a row another file row names.
    std::vector<const ParamMeta *> byName(record.values.size(), nullptr);
    std::set<const ParamMeta *> taken;
    for (std::size_t i = 0; i < record.values.size(); ++i) {
        byName[i] = dict.find(record.values[i].name);
        if (byName[i])
            taken.insert(byName[i]);
    }
    for (std::size_t i = 0; i < record.values.size(); ++i) {
        const ValueRow &row = record.values[i];
        RowMapping m;
        if (byName[i]) {
            m = classify(row, *byName[i], false, dict.family, major, t.mode);
        } else {
            bool byAddress = false;
            const ParamMeta *meta = findMeta(dict, row, &byAddress);
            if (meta && taken.insert(meta).second) {
                m = classify(row, *meta, true, dict.family, major, t.mode);
            } else if (meta) {
                m = {MapStatus::Unknown,
                     0,
                     row.name,
                     nullptr,
                     {row.name + ": its " + addressOf(*meta) + " belongs to " + meta->name +
                          ", which the file sets as well",
                      row.name + ": die " + addressOf(*meta) + " gehört zu " + meta->name +
                          ", das die Datei ebenfalls setzt"},
                     false};
            } else {
                m = {MapStatus::Unknown,
                     0,
                     row.name,
                     nullptr,
                     {row.name + " is not in " + dict.family + ": kept in the file, not applied",
                      row.name + " ist nicht in " + dict.family +
                          ": bleibt in der Datei, wird nicht übernommen"},
                     false};
            }
        }
        m.row = i;
        report.rows.push_back(std::move(m));
    }
    ignoredNotes(report);
    // A process value the file does not hold is not missing: files carry settings only.
    for (const ParamMeta &p : dict.params) {
        if (p.access != Access::ReadWrite || !isFileRow(p) || !p.appliesTo(major, t.mode) ||
            taken.count(&p))
            continue;
        report.rows.push_back({MapStatus::Missing,
                               RowMapping::kNoRow,
                               p.name,
                               &p,
                               {p.name + " is not in the file: the module keeps its value",
                                p.name + " fehlt in der Datei: das Modul behält seinen Wert"},
                               false});
    }
    return report;
}

std::size_t MapReport::count(MapStatus status) const
{
    return static_cast<std::size_t>(std::count_if(
        rows.begin(), rows.end(), [&](const RowMapping &r) { return r.status == status; }));
}

bool MapReport::clean() const
{
    return notes.empty() && std::all_of(rows.begin(), rows.end(), [](const RowMapping &r) {
               return r.status == MapStatus::Mapped;
           });
}

std::vector<const RowMapping *> MapReport::problems() const
{
    std::vector<const RowMapping *> out;
    for (const RowMapping &r : rows)
        if (r.status != MapStatus::Mapped)
            out.push_back(&r);
    return out;
}

std::vector<const RowMapping *> MapReport::ignoredForWriting() const
{
    std::vector<const RowMapping *> out;
    for (const RowMapping &r : rows)
        if (r.ignoredForWriting)
            out.push_back(&r);
    return out;
}

LocalText statusText(MapStatus status)
{
    switch (status) {
    case MapStatus::Mapped: return {"mapped", "übernommen"};
    case MapStatus::MappedByAddress: return {"mapped by address", "über Adresse übernommen"};
    case MapStatus::Unknown: return {"unknown", "unbekannt"};
    case MapStatus::OutOfRange: return {"out of range", "außerhalb des Bereichs"};
    case MapStatus::NotApplicable: return {"not applicable", "nicht zutreffend"};
    case MapStatus::TypeMismatch: return {"type mismatch", "falscher Typ"};
    case MapStatus::Missing: return {"missing", "fehlt"};
    }
    return {};
}

LocalText MapReport::summary() const
{
    LocalText out;
    for (MapStatus s :
         {MapStatus::Mapped, MapStatus::MappedByAddress, MapStatus::Unknown, MapStatus::OutOfRange,
          MapStatus::NotApplicable, MapStatus::TypeMismatch, MapStatus::Missing}) {
        const std::size_t n = count(s);
        if (n == 0 && s != MapStatus::Mapped)
            continue;
        const LocalText name = statusText(s);
        out.en += (out.en.empty() ? "" : ", ") + std::to_string(n) + " " + name.en;
        out.de += (out.de.empty() ? "" : ", ") + std::to_string(n) + " " + name.de;
    }
    return out;
}

} // namespace vt::dev::files
