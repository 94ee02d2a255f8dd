#include "wire_value.h"

#include "access/hcs_rows.h"
#include "hart/data_types.h"

#include <cmath>

namespace vt::dev::access {

std::optional<std::uint32_t> rawToWireBits(const ParamMeta &row, const RawValue &value)
{
    const std::size_t width = wireBytes(row.type);
    if (width == 0 || isText(value))
        return std::nullopt;
    const double number = rawNumber(value);
    if (!std::isfinite(number) || number < typeMin(row.type) || number > typeMax(row.type))
        return std::nullopt;
    if (row.isFloat())
        return hart::bitsFromFloat(static_cast<float>(number));
    if (std::trunc(number) != number)
        return std::nullopt;
    // Two's complement of the integer, cut to the type's width.
    const auto wide = static_cast<std::uint64_t>(static_cast<std::int64_t>(number));
    const std::uint64_t mask = width >= 4 ? 0xFFFFFFFFu : (std::uint64_t{1} << (8 * width)) - 1;
    return static_cast<std::uint32_t>(wide & mask);
}

double wireBitsToRaw(const ParamMeta &row, std::uint32_t bits)
{
    switch (row.type) {
    case RawType::Int8: return static_cast<std::int8_t>(static_cast<std::uint8_t>(bits & 0xFFu));
    case RawType::UInt8: return static_cast<double>(bits & 0xFFu);
    case RawType::Int16:
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(bits & 0xFFFFu));
    case RawType::UInt16: return static_cast<double>(bits & 0xFFFFu);
    case RawType::Int32: return static_cast<std::int32_t>(bits);
    case RawType::UInt32: return static_cast<double>(bits);
    case RawType::Float32: return static_cast<double>(hart::floatFromBits(bits));
    case RawType::String: break;
    }
    return 0;
}

std::optional<std::uint16_t> hcsWordOf(const ParamMeta &row, const RawValue &value)
{
    if (isText(value) || row.isString())
        return std::nullopt;
    const double number = rawNumber(value);
    if (!(number >= typeMin(row.type) && number <= typeMax(row.type)))
        return std::nullopt; // NaN fails both comparisons
    return rawToRegister(value);
}

} // namespace vt::dev::access
