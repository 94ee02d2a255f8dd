// The dictionary reader and the typed-value parser on arbitrary input: never crash, never hang.
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    auto loaded = vt::dev::loadDictionaries({{"fuzz.json", text}});
    if (loaded.ok()) {
        for (const std::string &family : loaded->families())
            for (const vt::dev::ParamMeta &p : loaded->find(family)->params)
                (void)vt::dev::formatValue(p, p.max, vt::dev::Language::German);
    }
    // The same bytes as typed input for a real row of every kind of scale.
    static const auto &builtin = vt::dev::builtinDictionaries();
    for (const char *name : {"C1.07", "0xB0", "E22"}) {
        if (const vt::dev::ParamMeta *p = builtin->find("opat")->find(name))
            (void)vt::dev::parseValue(*p, text, vt::dev::Language::German);
    }
    if (const vt::dev::ParamMeta *p = builtin->find("wandfluh-ed1")->find("dop_drivePos_AsideVal"))
        (void)vt::dev::parseValue(*p, text, vt::dev::Language::English);
    return 0;
}
