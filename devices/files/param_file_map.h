// Mapping a module of a parameter file onto a dictionary. Every file row gets a status and, unless
// it mapped plainly, a reason in both languages; dictionary rows the file does not set are listed
// too. The report is what the GUI's "what did not map" dialog and the CLI print. Pure, any
// thread; the report points into the dictionary, which must outlive it (builtinDictionaries()
// does).
#pragma once

#include "core/local_text.h"
#include "dict/dictionary.h"
#include "param_file.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace vt::dev::files {

enum class MapStatus {
    Mapped,          // same name: the value applies
    MappedByAddress, // name unknown here, same ID (HCS) or IND/PNU/instance (Wandfluh): applies,
                     // reported
    Unknown,         // not in this dictionary: kept in the file, not applied
    OutOfRange,      // outside the row's raw range (or a string longer than the row)
    NotApplicable,   // the row exists but not for this module's version or mode
    TypeMismatch, // text for a number row, a number for a text row, a fraction for a whole-number
                  // row
    Missing,      // a read/write row of the dictionary the file does not set
};

struct RowMapping
{
    static constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);

    MapStatus status = MapStatus::Mapped;
    std::size_t row = kNoRow;        // index in ModuleRecord::values; kNoRow for Missing
    std::string name;                // the file's name (the dictionary's for Missing)
    const ParamMeta *meta = nullptr; // the dictionary row, when there is one
    LocalText reason;                // empty for Mapped
    // A process or live value (file_rows.h): kept in the file, named in a module note, never
    // written; the status still says whether its value would have mapped.
    bool ignoredForWriting = false;

    bool applies() const
    {
        return status == MapStatus::Mapped || status == MapStatus::MappedByAddress;
    }
};

// The module the file is opened against; defaults to what the record itself says.
struct MapTarget
{
    std::string version; // "32.10" or "32"; only the major before the dot is compared
    std::string mode;    // "3"
};

struct MapReport
{
    std::string family; // the dictionary mapped onto
    // Module level: other family, version or mode than the file's; process and live values the
    // file holds, by name, ignored for writing.
    std::vector<LocalText> notes;
    std::vector<RowMapping> rows; // file rows in file order, then Missing rows in dictionary order

    std::size_t count(MapStatus status) const;
    // Everything applies and nothing is missing, and no module-level note.
    bool clean() const;
    // Rows that need the user's attention (all but Mapped).
    std::vector<const RowMapping *> problems() const;
    // File rows that are process or live values: never written, whatever their status.
    std::vector<const RowMapping *> ignoredForWriting() const;
    // "180 mapped, 1 by address, 2 unknown, 1 out of range, 3 missing"
    LocalText summary() const;
};

LocalText statusText(MapStatus status);

// The dictionary row a file row names: by name, else by ID, else by IND/PNU/instance.
// `byAddress` (optional) tells which.
const ParamMeta *findMeta(const Dictionary &dict, const ValueRow &row, bool *byAddress = nullptr);

MapReport mapModule(const ModuleRecord &record, const Dictionary &dict,
                    const std::optional<MapTarget> &target = std::nullopt);

} // namespace vt::dev::files
