// Parameter files (.vtpar, docs/FILE-FORMAT.md): the in-memory document and its JSON codec.
// Raw values are authoritative, display texts are for people and never read back, and keys and
// rows this version does not know are kept and written back unchanged. Pure functions; a ParamFile
// is a plain value owned by its caller (any thread, one at a time).
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "dict/dictionary.h"
#include "dict/raw_value.h"

#include <chrono>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev::files {

inline constexpr const char *kFormatName = "valvetune-parameters"; // the "format" key
inline constexpr int kFormatVersion = 1;                           // the major this reader knows
inline constexpr std::size_t kMaxFileBytes = 16u * 1024u * 1024u;
inline constexpr int kMaxDepth = 32;           // nesting of arrays/objects, unknown keys included
inline constexpr std::size_t kMaxModules = 64; // a fold holds at most 5 DMA / 1+7 OPAT modules
inline constexpr std::size_t kMaxRows = 4096;  // per module; the largest dictionary has < 600

// One parameter value. The name identifies the row; id (HCS) and ind/pnu/instance (Wandfluh)
// are the fallback when a dictionary renamed it.
struct ValueRow
{
    std::string name;
    std::optional<int> id;
    std::optional<int> ind, pnu, instance;
    RawValue raw = 0.0;
    std::string display; // for people; ignored by every reader of the value
    nlohmann::json extra = nlohmann::json::object(); // unknown keys, written back as read

    bool operator==(const ValueRow &) const = default;
};

// One module: where it sits in the fold, what it identified as, and its values.
struct ModuleRecord
{
    int address = 0;     // HCS SADR / unit id, HART poll address, CAN node (0..255)
    std::string family;  // dictionary family id, "dma-pb-v32"
    std::string version; // as identified, "32.10"; may be empty
    std::string mode;    // HCS E00, "3"; may be empty
    std::string label;   // the user's name for the module ("Press 1, axis A")
    std::vector<ValueRow> values;
    nlohmann::json extra = nlohmann::json::object();

    const ValueRow *find(const std::string &name) const;
    bool operator==(const ModuleRecord &) const = default;
};

// A whole file: one module or a whole fold.
struct ParamFile
{
    int formatVersion = kFormatVersion;
    std::string tool;    // "ValveTune 0.1.0"
    std::string created; // ISO 8601 UTC, "2024-05-02T09:30:00Z"
    std::string note;
    std::vector<ModuleRecord> modules;
    nlohmann::json extra = nlohmann::json::object();

    const ModuleRecord *findModule(int address) const;
    bool operator==(const ParamFile &) const = default;
};

enum class FileErrc {
    TooLarge,      // over kMaxFileBytes
    Syntax,        // not JSON
    TooDeep,       // nesting over kMaxDepth
    NotAParamFile, // JSON, but no "format": "valvetune-parameters"
    NewerVersion,  // formatVersion above kFormatVersion
    WrongType,     // a known key holds the wrong JSON type
    MissingKey,    // a required key is absent
    BadValue,      // right type, impossible value (address 300, formatVersion 0, NaN text)
    TooMany,       // modules or rows over the limits
    Duplicate,     // two modules with one address, two rows with one name
};

struct FileError
{
    FileErrc code = FileErrc::Syntax;
    LocalText message;
    std::string location; // JSON pointer of the offending value ("/modules/0/values/3/raw")
    std::size_t line = 0; // Syntax, TooDeep: where in the text (1-based); else 0
    std::size_t column = 0;

    // "/modules/0/values/3/raw: \"raw\" must be a number or a text, not boolean",
    // "Zeile 4, Spalte 12: kein gültiger JSON-Text …"
    LocalText text() const;
};

[[nodiscard]] Result<ParamFile, FileError> parseParamFile(std::string_view text);

// Stable key order, one value row per line, integers as integers, floats in the shortest form
// that reads back exactly. With a dictionary set, display texts are recomputed from the raw
// values in `lang` (cooking.h formatValue); without one, they are written as they are held.
// parseParamFile(writeParamFile(f, …)) == f (display texts aside when recomputed).
std::string writeParamFile(const ParamFile &file, const DictionarySet *forDisplay = nullptr,
                           Language lang = Language::English);

// A raw number as the file writes it: "1000", "1.5", "-0.0"; "NaN", "Infinity", "-Infinity".
std::string rawNumberText(double raw);

// A row for a dictionary parameter, with its addresses filled in.
ValueRow makeValueRow(const ParamMeta &meta, RawValue raw);

// "2024-05-02T09:30:00Z"
std::string isoUtc(std::chrono::system_clock::time_point when);

} // namespace vt::dev::files
