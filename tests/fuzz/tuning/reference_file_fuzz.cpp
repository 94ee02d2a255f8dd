// The reference-file reader (model/tuning/reference_file.h) on arbitrary input. It never crashes,
// and a reference it accepts writes out and reads back with the same tests and settings.
#include "model/tuning/reference_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

using namespace vt::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char *>(data), size);
    auto parsed = parseReferenceFile(input);
    if (!parsed.ok())
        return 0;
    auto again = parseReferenceFile(referenceJson(*parsed));
    if (!again.ok())
        std::abort(); // what was read must write out readable
    if (again->tests.size() != parsed->tests.size() ||
        again->settings.size() != parsed->settings.size() ||
        again->figures.size() != parsed->figures.size())
        std::abort();
    return 0;
}
