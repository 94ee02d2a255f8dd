// The fold plan file (.vtfold): a FoldPlan as versioned JSON that the wizard and the editor open
// and save. Qt-free and bounded (size, module count, string length) so a broken or hostile file
// gives a typed error, never a crash; fuzzed by tests/fuzz/fold/fold_plan_fuzz.cpp. The error
// says what is wrong; foldFileErrorText() (fold_plan_file_text.cpp, Qt) says it to people.
#pragma once

#include "core/result.h"
#include "fold_plan.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

class QString;

namespace vt::model {

inline constexpr std::string_view kFoldPlanFormat = "valvetune-fold-plan"; // "format" member
inline constexpr int kFoldPlanVersion = 1;                                 // "formatVersion" member
inline constexpr std::string_view kFoldPlanSuffix = "vtfold";              // file name suffix
inline constexpr std::size_t kFoldPlanMaxBytes = 256 * 1024;
inline constexpr std::size_t kFoldPlanMaxModules = 32; // DMA E22 reaches 32 (CMD 3/6)
inline constexpr std::size_t kFoldPlanMaxText = 4096;  // bytes per free-text member

enum class FoldFileErrc {
    TooLarge,      // more than kFoldPlanMaxBytes
    NotJson,       // syntax error (offset = byte position)
    WrongFormat,   // not an object, or "format" is not kFoldPlanFormat
    NewerVersion,  // "formatVersion" > kFoldPlanVersion: written by a newer ValveTune
    MissingMember, // required member absent (member = its path)
    BadMember,     // wrong type or out of bounds (member = its path, e.g. "modules[2].address")
    Io,            // the file could not be read or written
};

// What exactly is wrong, beyond the code.
enum class FoldFileProblem {
    None,
    TooDeep,        // WrongFormat: nested deeper than a plan can be
    NumberTooLarge, // NotJson: a number beyond double
    ReadFailed,     // Io
    WriteFailed,    // Io
    NotWholeNumber, // BadMember …
    OutOfBounds,    // low … high
    NotText,
    TooLong, // high = the limit in bytes
    UnknownNode,
    NotList,
    TooManyEntries, // high = the limit
    NotObject,
};

struct FoldFileError
{
    FoldFileErrc code = FoldFileErrc::NotJson;
    std::string member;     // JSON path of the offending member, when there is one
    std::size_t offset = 0; // NotJson: byte offset of the syntax error
    FoldFileProblem problem = FoldFileProblem::None;
    long long low = 0;  // OutOfBounds: the lower bound
    long long high = 0; // OutOfBounds: the upper bound; TooLong, TooManyEntries: the limit;
                        // NewerVersion: the file's format version
    std::string path;   // Io: the file

    bool operator==(const FoldFileError &) const = default;
};

// The error as a sentence for people, in the language shown now (Qt; fold_plan_file_text.cpp).
QString foldFileErrorText(const FoldFileError &error);

// Pretty-printed JSON ending in a newline; members in a fixed order, options only when set.
std::string writeFoldPlan(const FoldPlan &plan);
// Accepts what writeFoldPlan writes (and the same version with unknown members ignored, so a
// later minor addition still opens). Values are type- and bound-checked but NOT checked for
// sense (duplicates, ranges against dictionaries): that is checkFoldPlan's job.
dev::Result<FoldPlan, FoldFileError> parseFoldPlan(std::string_view text);

// File helpers (UTF-8 path). save writes atomically (temp file + rename).
dev::Result<FoldPlan, FoldFileError> loadFoldPlanFile(const std::string &path);
std::optional<FoldFileError> saveFoldPlanFile(const FoldPlan &plan, const std::string &path);

} // namespace vt::model
