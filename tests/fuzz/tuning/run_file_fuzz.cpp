// The run-file reader (model/tuning/run_file.h) on arbitrary input: the JSON and the CSV are the
// input's two halves around its first NUL (or all JSON without one). It never crashes, and a run
// it accepts writes out and reads back to the same recording.
#include "model/tuning/run_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

using namespace vt::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char *>(data), size);
    const std::size_t cut = input.find('\0');
    const std::string_view json = input.substr(0, cut);
    const std::string_view csv =
        cut == std::string_view::npos ? std::string_view() : input.substr(cut + 1);
    auto parsed = parseRunFiles(json, csv);
    if (!parsed.ok())
        return 0;
    const std::string json2 = runJson(*parsed);
    const std::string csv2 = runCsv(*parsed);
    auto again = parseRunFiles(json2, csv2);
    if (!again.ok())
        std::abort(); // what was read must write out readable
    if (again->channels.size() != parsed->channels.size() ||
        again->setValueSamples.t.size() != parsed->setValueSamples.t.size())
        std::abort();
    return 0;
}
