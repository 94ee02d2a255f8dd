// Explains Modbus RTU and TCP ADUs field by field for the inspector and the CLI (STYLE.md rule 7),
// naming registers as HCS parameter IDs and exception codes with their HCS meaning.
#pragma once

#include "core/direction.h"
#include "core/field_span.h"
#include "hcs/describe.h"
#include "hcs/types.h"

#include <cstdint>
#include <optional>
#include <span>

namespace vt::dev::modbus {

struct DescribeOptions
{
    Direction direction = Direction::Request;
    hcs::Family family = hcs::Family::Dma;       // which HCS table explains exception codes
    std::optional<std::uint16_t> requestStart{}; // FC 3 response: the request's first register
    hcs::ParameterHooks parameters{}; // register = parameter ID → names / cooked values
};

// Never fail: fields as far as the bytes allow, `error` = what decodeRtu…/decodeTcp… report.
Description describeRtu(std::span<const std::uint8_t> adu,
                        const DescribeOptions &options); // "modbus-rtu"
Description describeTcp(std::span<const std::uint8_t> adu,
                        const DescribeOptions &options); // "modbus-tcp"

} // namespace vt::dev::modbus
