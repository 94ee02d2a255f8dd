// describeLogged: explains a frame as a link of one LinkProtocol carried it (the telegram log
// records the protocol of every frame), for the inspector's list and detail pane. Fills the two
// gaps between the links' wire images and describeAny: the node image is a gateway telegram plus
// padding, and a CANopen frame is logged as its 16-byte SocketCAN image.
#pragma once

#include "hcs/describe.h"
#include "inspect/describe_any.h"

#include <optional>
#include <span>
#include <string>

namespace vt::dev::inspect {

// `options.protocol` is replaced by the link's frame format. A 16-byte CANopen record is
// unwrapped: its fields keep their offsets in the 16 bytes (data at 8..15) and the CAN id,
// length and padding become fields of their own. `firstId`: for a CMD 3 / FC 3 answer, the
// request's first ID, so the data words are named (answers do not carry their IDs). Fails like
// describeAny.
Result<Description, std::string>
describeLogged(LinkProtocol link, std::span<const std::uint8_t> bytes, AnyOptions options,
               std::optional<std::uint16_t> firstId = std::nullopt);

// HCS parameter names and cooked values from a dictionary (nullptr = none), as describeAny uses.
hcs::ParameterHooks parameterHooks(const Dictionary *dictionary);

// The gateway codec's options for `options`: family, direction, the CMD 15 profile named by its
// key and the HCS parameter hooks. Fails for an unknown profile key.
Result<hcs::DescribeOptions, std::string> gatewayOptions(const AnyOptions &options);

// The same for a SocketCAN image alone (also the decode box's 16-byte CANopen paste).
Description describeSocketCanImage(std::span<const std::uint8_t> image);

} // namespace vt::dev::inspect
