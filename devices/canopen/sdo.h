// CANopen SDO messages (CiA 301 §7.2.4.3): expedited upload/download, segmented transfer
// (initiate and segments recognised and described), block transfer (recognised), abort; plus the
// SDO COB-ID rule (request 0x600 + node, response 0x580 + node).
#pragma once

#include "canopen/can_frame.h"
#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/direction.h"
#include "core/field_span.h"
#include "core/local_text.h"
#include "core/result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::canopen {

inline constexpr std::uint16_t kSdoRequestBase =
    0x600; // client → server (CiA 301 §7.3.3 pre-defined set)
inline constexpr std::uint16_t kSdoResponseBase = 0x580; // server → client
inline constexpr std::uint8_t kMaxNodeId = 127;
inline constexpr std::size_t kSdoSize = 8;

std::uint16_t sdoRequestId(std::uint8_t node);
std::uint16_t sdoResponseId(std::uint8_t node);

// A COB-ID of the default SDO channel: node 1..127 and the direction (request = client → server).
struct SdoChannel
{
    std::uint8_t node = 0;
    Direction direction = Direction::Request;
    bool operator==(const SdoChannel &) const = default;
};
std::optional<SdoChannel> sdoChannel(std::uint32_t cobId);

// The command specifier meanings (CiA 301 §7.2.4.3.3 ff.), named by what the message does.
enum class SdoCommand : std::uint8_t {
    InitiateDownloadRequest,  // ccs 1: expedited write, or segmented write initiate
    DownloadSegmentRequest,   // ccs 0
    InitiateUploadRequest,    // ccs 2: read
    UploadSegmentRequest,     // ccs 3
    BlockUploadRequest,       // ccs 5 (recognised only)
    BlockDownloadRequest,     // ccs 6 (recognised only)
    InitiateDownloadResponse, // scs 3: write confirmed
    DownloadSegmentResponse,  // scs 1
    InitiateUploadResponse,   // scs 2: expedited read value, or segmented read initiate
    UploadSegmentResponse,    // scs 0
    BlockDownloadResponse,    // scs 5 (recognised only)
    BlockUploadResponse,      // scs 6 (recognised only)
    Abort,                    // cs 4, either direction
};

// Who sends `command`; an abort can come from either side and is reported as Request here.
Direction directionOf(SdoCommand command);
bool isBlockTransfer(SdoCommand command);

struct Sdo
{
    SdoCommand command = SdoCommand::InitiateUploadRequest;
    std::uint16_t index = 0; // initiate, block and abort messages
    std::uint8_t subindex = 0;
    bool expedited = false;     // e bit of an initiate message
    bool sizeIndicated = false; // s bit of an initiate message
    Bytes data;                 // expedited: 1..4 bytes (4 without size); segments: 0..7 bytes
    std::uint32_t size = 0;     // segmented initiate with s = 1: bytes to transfer
    bool toggle = false;        // t bit of segment messages
    bool last = false;          // c bit of segment messages: no more segments
    std::uint32_t abortCode = 0;
    std::array<std::uint8_t, 8> blockRaw{}; // block messages: the 8 bytes, not interpreted

    bool operator==(const Sdo &) const = default;
};

// Builders for the client (ValveTune) and the server (simulator). Values are little-endian on
// CANopen (CiA 301 §7.1.3.1), unlike the other fieldbuses (see docs/protocol-notes).
Sdo expeditedDownload(std::uint16_t index, std::uint8_t subindex,
                      std::span<const std::uint8_t> data);
Sdo expeditedDownload(std::uint16_t index, std::uint8_t subindex, std::uint32_t value,
                      std::size_t bytes);
Sdo uploadRequest(std::uint16_t index, std::uint8_t subindex);
Sdo downloadResponse(std::uint16_t index, std::uint8_t subindex);
Sdo expeditedUploadResponse(std::uint16_t index, std::uint8_t subindex,
                            std::span<const std::uint8_t> data);
Sdo expeditedUploadResponse(std::uint16_t index, std::uint8_t subindex, std::uint32_t value,
                            std::size_t bytes);
Sdo abortTransfer(std::uint16_t index, std::uint8_t subindex, std::uint32_t abortCode);

// Little-endian value of an expedited transfer's data (0..4 bytes).
std::uint32_t expeditedValue(const Sdo &sdo);

// Always 8 bytes (CiA 301: SDOs use DLC 8, unused bytes 0). BadValue when the fields do not fit
// (expedited data 0 or > 4 bytes, segment data > 7 bytes).
Result<Bytes, DecodeError> encodeSdo(const Sdo &sdo);
// The 8 data bytes of an SDO sent in `direction` (its COB-ID decides). Fewer or more is an error.
Result<Sdo, DecodeError> decodeSdo(std::span<const std::uint8_t> data, Direction direction);

// CAN frames of the default SDO channel of `node` (1..127). The command decides the COB-ID;
// an abort goes the way `abortFrom` says (the server aborts with 0x580 + node).
Result<CanFrame, DecodeError> toCanFrame(const Sdo &sdo, std::uint8_t node,
                                         Direction abortFrom = Direction::Request);
struct SdoMessage
{
    SdoChannel channel;
    Sdo sdo;
};
Result<SdoMessage, DecodeError> fromCanFrame(const CanFrame &frame);

struct DescribeOptions
{
    std::optional<std::uint32_t> cobId;       // decides the direction when it is an SDO COB-ID
    Direction direction = Direction::Request; // used without a COB-ID
};
// The 8 data bytes (plus the COB-ID from the options); the id row is added when known.
Description describeSdo(std::span<const std::uint8_t> data, const DescribeOptions &options = {});
Description describeSdo(const CanFrame &frame);

// What the message does, e.g. "initiate download (expedited write)".
LocalText commandText(const Sdo &sdo);

// CiA 301 §7.2.4.3.17 SDO abort codes (abort_codes.cpp).
LocalText abortCodeText(std::uint32_t code);
bool isKnownAbortCode(std::uint32_t code);
// Every code of that table, in table order (completeness tests walk it).
std::vector<std::uint32_t> knownAbortCodes();

} // namespace vt::dev::canopen
