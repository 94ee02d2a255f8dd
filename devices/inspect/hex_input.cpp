#include "hex_input.h"

#include "canopen/can_frame.h"
#include "core/hex.h"

namespace vt::dev::inspect {
namespace {

bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && isBlank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back()))
        text.remove_suffix(1);
    return text;
}

} // namespace

Result<HexInput, HexInputError> parseHexInput(std::string_view text)
{
    if (text.size() > kMaxInputChars)
        return HexInputError{kMaxInputChars,
                             "input longer than " + std::to_string(kMaxInputChars) + " characters"};
    const std::string_view body = trimmed(text);
    const std::size_t lead = static_cast<std::size_t>(body.data() - text.data());
    HexInput out;
    if (body.find('#') != std::string_view::npos) {
        // candump notation: one CAN frame with its identifier.
        const auto frame = canopen::parseCandump(body);
        if (!frame)
            return HexInputError{lead + frame.error().offset, "not a candump frame (<id>#<data>)"};
        out.cobId = frame->id;
        const auto payload = frame->payload();
        out.bytes.assign(payload.begin(), payload.end());
        return out;
    }
    auto bytes = parseHex(body);
    if (!bytes)
        return HexInputError{lead + bytes.error().position, bytes.error().reason};
    if (bytes->size() > kMaxFrameBytes)
        return HexInputError{lead, "more than " + std::to_string(kMaxFrameBytes) + " bytes"};
    out.bytes = std::move(*bytes);
    return out;
}

} // namespace vt::dev::inspect
