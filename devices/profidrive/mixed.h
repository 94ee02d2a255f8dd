// The mixed process image of OPAT manual §5.6: the OPAT master as a PROFIdrive axis (standard
// telegram 1, 4 bytes) followed by a CMD 15 telegram for the node (master + CAN slaves).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"
#include "hcs/cmd15.h"
#include "hcs/telegram.h"
#include "telegram1.h"

#include <cstdint>
#include <span>
#include <variant>

namespace vt::dev::profidrive {

// PLC → node: STW1 NSOLL_A | TADR SNUM 15 DAT0.1 … (§5.6 "Send telegram by the PLC", 17 bytes for
// one master and one slave).
struct MixedRequest
{
    Setpoint drive;
    hcs::CyclicRequest node; // OPAT family: modules[0] = master (SADR 0)

    bool operator==(const MixedRequest &) const = default;
};

// Node → PLC: ZSW1 NIST_A | TADR SADR 15 status VALUE1 VALUE2 (13 bytes), or an error frame.
struct MixedResponse
{
    Actual drive;
    std::variant<hcs::CyclicResponse, hcs::ExceptionResponse> node;

    bool operator==(const MixedResponse &) const = default;
};

Result<Bytes, DecodeError> encode(const MixedRequest &request,
                                  hcs::Family family = hcs::Family::Opat);
Bytes encode(const MixedResponse &response);

// Errors from the CMD 15 part carry offsets within the whole image (4 + …).
Result<MixedRequest, DecodeError> decodeMixedRequest(std::span<const std::uint8_t> image,
                                                     const hcs::DecodeOptions &options = {
                                                         hcs::Family::Opat, false});
Result<MixedResponse, DecodeError> decodeMixedResponse(std::span<const std::uint8_t> image,
                                                       const hcs::DecodeOptions &options = {
                                                           hcs::Family::Opat, false});

} // namespace vt::dev::profidrive
