// Field description of one HART frame for the telegram inspector and the CLI (STYLE.md rule 7):
// link layer (HART-7 manual §2.3) plus the typed payload of universal (§5.1) and
// device-specific (§4.4.1) commands.
#pragma once

#include "core/field_span.h"

#include <cstdint>
#include <span>

namespace vt::dev::hart {

struct DescribeOptions
{
    bool payload = true; // describe the data bytes field by field
};

// Bytes as on the wire: optional preambles, delimiter … checksum. Fields cover as much as is
// present; `error` is set for any link-layer fault and for a malformed payload.
Description describeFrame(std::span<const std::uint8_t> bytes, const DescribeOptions &options = {});

} // namespace vt::dev::hart
