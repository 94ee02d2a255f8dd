// Explains an HCS node telegram (CMD 3 / 6 / 15 and error responses) field by field for the
// telegram inspector and the CLI (STYLE.md rule 7); codecs: telegram.h, cmd15.h.
#pragma once

#include "core/direction.h"
#include "core/field_span.h"
#include "core/local_text.h"
#include "profiles.h"
#include "types.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

namespace vt::dev::hcs {

// Optional links to the parameter dictionary, so that rows can say "ID 0x0030 (C1.07)" and
// "1.000 V". Without them IDs and values are shown raw.
struct ParameterHooks
{
    std::function<std::optional<LocalText>(std::uint16_t id)> name{};
    std::function<std::optional<LocalText>(std::uint16_t id, std::uint16_t raw)> cook{};

    // "<prefix> 0x0030 (C1.07 …)": the ID with the dictionary's name when the hook knows it.
    LocalText idText(std::uint16_t id, const LocalText &prefix) const;
    // "1.000 V, 0x03E8" when the value can be cooked (and the ID is known), else "0x03E8".
    LocalText valueText(std::uint16_t id, std::uint16_t raw, bool idKnown) const;
};

struct DescribeOptions
{
    Family family = Family::Dma;
    Direction direction = Direction::Request; // responses: bit 7 of CMD marks an error frame
    // CMD 15 layout (what VALUE1/VALUE2 and the bits mean). Unset: defaultProfile(family), and the
    // description states that it was assumed.
    std::optional<Profile> profile{};
    bool allowPadding = false;           // see DecodeOptions::allowPadding
    bool opatPrintedStatusOrder = false; // see statusLowBits()
    std::optional<std::uint16_t>
        firstId{}; // CMD 3 response: the request's first ID, to name DAT1..n
    ParameterHooks parameters{};
};

// Never fails: on a bad frame the fields go as far as the bytes allow and `error` is set (the same
// error the decoder returns). protocol = "gateway".
Description describe(std::span<const std::uint8_t> frame, const DescribeOptions &options);

} // namespace vt::dev::hcs
