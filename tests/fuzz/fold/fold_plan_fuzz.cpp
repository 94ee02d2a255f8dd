// The fold plan file reader (.vtfold) on arbitrary input (STYLE.md rule 12: never crash
// on a bad file), and for every plan it accepts: the written text reads back to the same plan and
// writes again to the same text, and the checks and the PLC configuration never fail on it.
// Qt-free: the fold plan value, its file, checks and PLC configuration are compiled in directly.
#include "dict/dictionary_loader.h"
#include "model/fold/fold_check.h"
#include "model/fold/fold_plan_file.h"
#include "model/fold/plc_config.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

using namespace vt::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    auto parsed = parseFoldPlan(text);
    if (!parsed.ok()) {
        if (parsed.error().code == FoldFileErrc::BadMember &&
            parsed.error().problem == FoldFileProblem::None)
            __builtin_trap();
        return 0;
    }
    const std::string written = writeFoldPlan(*parsed);
    auto again = parseFoldPlan(written);
    if (!again.ok()) {
        if (again.error().code == FoldFileErrc::TooLarge) // pretty-printing made it wider
            return 0;
        __builtin_trap();
    }
    if (!(*again == *parsed) || writeFoldPlan(*again) != written)
        __builtin_trap();

    static const auto &builtin = vt::dev::builtinDictionaries();
    const auto findings = checkFoldPlan(*parsed, builtin.ok() ? &*builtin : nullptr);
    for (const FoldFinding &f : findings)
        if (f.sentences.empty())
            __builtin_trap();
    const auto config = buildPlcConfig(*parsed);
    if (config.ok()) {
        if (config->output.size() != static_cast<std::size_t>(config->outputBytes) ||
            config->exampleRequestBytes.size() != static_cast<std::size_t>(config->outputBytes))
            __builtin_trap();
    } else if (!hasErrors(findings)) {
        __builtin_trap(); // a plan the PLC sheet refuses must have an error finding
    }
    return 0;
}
