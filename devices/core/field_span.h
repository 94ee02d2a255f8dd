// FieldSpan / Description: how every codec explains a frame (STYLE.md rule 7). Codecs describe
// fields once; the inspector, the CLI and the tests only render them.
#pragma once

#include "decode_error.h"
#include "local_text.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev {

struct FieldSpan
{
    std::string key;        // stable machine name: "TADR", "DAT1H", "pdu.function"
    std::size_t offset = 0; // first byte in the frame
    std::size_t length = 0; // bytes covered (0 for a purely explanatory row)
    int depth = 0;          // 0 = top level; children follow their parent with depth + 1
    std::string value;      // the value as a person reads it: "0x23", "1000", "-3000"
    LocalText text;         // meaning: "telegram address", "d1.11 actual value (branch 1)"
};

struct Description
{
    std::string protocol;             // "gateway", "modbus-rtu", …
    std::vector<FieldSpan> fields;    // as far as decoding got, also on error
    std::optional<DecodeError> error; // set when the frame is not valid
    LocalText summary;                // one line for the telegram list

    bool ok() const { return !error.has_value(); }
    // The first field with this key, or nullptr (tests, the inspector's "jump to field").
    const FieldSpan *field(std::string_view key) const
    {
        for (const FieldSpan &f : fields)
            if (f.key == key)
                return &f;
        return nullptr;
    }
};

} // namespace vt::dev
