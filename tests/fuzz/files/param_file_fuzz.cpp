// The parameter file reader on arbitrary input (STYLE.md rule 12: never crash on a bad file), and
// for every file it accepts: the written text reads back and writes again to the same text
// (nothing is dropped on save), mapping and CSV export never fail.
#include "dict/dictionary_loader.h"
#include "files/param_csv.h"
#include "files/param_file.h"
#include "files/param_file_map.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

using namespace vt::dev;
using namespace vt::dev::files;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    auto parsed = parseParamFile(text);
    if (!parsed.ok()) {
        (void)parsed.error().text();
        return 0;
    }
    static const auto &builtin = builtinDictionaries();
    const DictionarySet *set = builtin.ok() ? &*builtin : nullptr;

    const std::string plain = writeParamFile(*parsed);
    auto again = parseParamFile(plain);
    if (!again.ok()) {
        if (again.error().code == FileErrc::TooLarge) // the written layout is wider than the input
            return 0;
        __builtin_trap();
    }
    if (writeParamFile(*again) != plain)
        __builtin_trap();

    for (const Language lang : {Language::English, Language::German}) {
        const std::string cooked = writeParamFile(*parsed, set, lang);
        auto back = parseParamFile(cooked);
        if (!back.ok() && back.error().code != FileErrc::TooLarge)
            __builtin_trap();
        for (const ModuleRecord &m : parsed->modules) {
            const Dictionary *dict = set ? set->find(m.family) : nullptr;
            if (!dict && set) // foreign family: map onto a real one anyway
                dict = set->find(m.address % 2 ? "dma-pb-v32" : "wandfluh-sd7");
            if (dict) {
                const MapReport report = mapModule(m, *dict, MapTarget{m.version, m.mode});
                (void)report.summary();
                (void)report.problems();
            }
            (void)exportCsv(m, dict, {lang, lang == Language::German});
        }
    }
    return 0;
}
