// Explains PROFIdrive standard telegram 1 (and the §5.6 mixed image with a CMD 15 telegram
// behind it) field by field for the inspector and the CLI (STYLE.md rule 7).
#pragma once

#include "core/direction.h"
#include "core/field_span.h"
#include "hcs/describe.h"

#include <cstdint>
#include <span>

namespace vt::dev::profidrive {

enum class Layout : std::uint8_t {
    Auto,       // 4 bytes: telegram 1; longer: mixed image
    Telegram1,  // exactly STW1/NSOLL_A or ZSW1/NIST_A
    MixedCmd15, // OPAT manual §5.6: telegram 1 followed by a CMD 15 telegram
};

struct DescribeOptions
{
    Direction direction = Direction::Request;
    Layout layout = Layout::Auto;
    double voltsAt100Percent = 10.0; // N2 100 % (ARCHITECTURE.md "PROFIdrive N2")
    // The CMD 15 part; its family defaults to OPAT (the only family with PROFIdrive), its
    // direction is taken from `direction`.
    hcs::DescribeOptions node{hcs::Family::Opat};
};

// protocol = "profidrive". CMD 15 rows of a mixed image keep their keys ("TADR", "DAT0.1", …)
// with offsets within the whole image.
Description describe(std::span<const std::uint8_t> bytes, const DescribeOptions &options);

} // namespace vt::dev::profidrive
