#include "canopen/sdo.h"

#include "core/byte_reader.h"

#include <algorithm>
#include <string>

namespace vt::dev::canopen {
namespace {

// Command specifier = bits 7..5 of byte 0 (CiA 301 §7.2.4.3).
constexpr std::uint8_t kCsShift = 5;
constexpr std::uint8_t kToggleBit = 0x10;

std::uint8_t cs(std::uint8_t byte0)
{
    return static_cast<std::uint8_t>(byte0 >> kCsShift);
}

DecodeError badValue(std::string detail)
{
    return DecodeError{DecodeErrc::BadValue, 0, 0, std::move(detail)};
}

std::optional<SdoCommand> commandFor(std::uint8_t specifier, Direction direction)
{
    if (direction == Direction::Request) {
        switch (specifier) {
        case 0: return SdoCommand::DownloadSegmentRequest;
        case 1: return SdoCommand::InitiateDownloadRequest;
        case 2: return SdoCommand::InitiateUploadRequest;
        case 3: return SdoCommand::UploadSegmentRequest;
        case 4: return SdoCommand::Abort;
        case 5: return SdoCommand::BlockUploadRequest;
        case 6: return SdoCommand::BlockDownloadRequest;
        default: return std::nullopt;
        }
    }
    switch (specifier) {
    case 0: return SdoCommand::UploadSegmentResponse;
    case 1: return SdoCommand::DownloadSegmentResponse;
    case 2: return SdoCommand::InitiateUploadResponse;
    case 3: return SdoCommand::InitiateDownloadResponse;
    case 4: return SdoCommand::Abort;
    case 5: return SdoCommand::BlockDownloadResponse;
    case 6: return SdoCommand::BlockUploadResponse;
    default: return std::nullopt;
    }
}

std::uint8_t specifierOf(SdoCommand command)
{
    switch (command) {
    case SdoCommand::DownloadSegmentRequest: return 0;
    case SdoCommand::InitiateDownloadRequest: return 1;
    case SdoCommand::InitiateUploadRequest: return 2;
    case SdoCommand::UploadSegmentRequest: return 3;
    case SdoCommand::BlockUploadRequest: return 5;
    case SdoCommand::BlockDownloadRequest: return 6;
    case SdoCommand::UploadSegmentResponse: return 0;
    case SdoCommand::DownloadSegmentResponse: return 1;
    case SdoCommand::InitiateUploadResponse: return 2;
    case SdoCommand::InitiateDownloadResponse: return 3;
    case SdoCommand::BlockDownloadResponse: return 5;
    case SdoCommand::BlockUploadResponse: return 6;
    case SdoCommand::Abort: return 4;
    }
    return 7;
}

bool isInitiateWithData(SdoCommand c)
{
    return c == SdoCommand::InitiateDownloadRequest || c == SdoCommand::InitiateUploadResponse;
}

bool isSegmentWithData(SdoCommand c)
{
    return c == SdoCommand::DownloadSegmentRequest || c == SdoCommand::UploadSegmentResponse;
}

Bytes littleEndian(std::uint32_t value, std::size_t bytes)
{
    Bytes out;
    for (std::size_t i = 0; i < bytes && i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    return out;
}

void writeU32le(ByteWriter &w, std::uint32_t v)
{
    w.u16le(static_cast<std::uint16_t>(v)).u16le(static_cast<std::uint16_t>(v >> 16));
}

std::uint32_t readU32le(ByteReader &r)
{
    const std::uint32_t low = r.u16le();
    const std::uint32_t high = r.u16le();
    return high << 16 | low;
}

} // namespace

std::uint16_t sdoRequestId(std::uint8_t node)
{
    return static_cast<std::uint16_t>(kSdoRequestBase + (node & 0x7F));
}

std::uint16_t sdoResponseId(std::uint8_t node)
{
    return static_cast<std::uint16_t>(kSdoResponseBase + (node & 0x7F));
}

std::optional<SdoChannel> sdoChannel(std::uint32_t cobId)
{
    if (cobId > kSdoRequestBase && cobId <= kSdoRequestBase + kMaxNodeId)
        return SdoChannel{static_cast<std::uint8_t>(cobId - kSdoRequestBase), Direction::Request};
    if (cobId > kSdoResponseBase && cobId <= kSdoResponseBase + kMaxNodeId)
        return SdoChannel{static_cast<std::uint8_t>(cobId - kSdoResponseBase), Direction::Response};
    return std::nullopt;
}

Direction directionOf(SdoCommand command)
{
    switch (command) {
    case SdoCommand::InitiateDownloadRequest:
    case SdoCommand::DownloadSegmentRequest:
    case SdoCommand::InitiateUploadRequest:
    case SdoCommand::UploadSegmentRequest:
    case SdoCommand::BlockUploadRequest:
    case SdoCommand::BlockDownloadRequest:
    case SdoCommand::Abort: return Direction::Request;
    default: return Direction::Response;
    }
}

bool isBlockTransfer(SdoCommand c)
{
    return c == SdoCommand::BlockUploadRequest || c == SdoCommand::BlockDownloadRequest ||
           c == SdoCommand::BlockDownloadResponse || c == SdoCommand::BlockUploadResponse;
}

Sdo expeditedDownload(std::uint16_t index, std::uint8_t subindex,
                      std::span<const std::uint8_t> data)
{
    Sdo s;
    s.command = SdoCommand::InitiateDownloadRequest;
    s.index = index;
    s.subindex = subindex;
    s.expedited = true;
    s.sizeIndicated = true;
    s.data.assign(data.begin(), data.end());
    return s;
}

Sdo expeditedDownload(std::uint16_t index, std::uint8_t subindex, std::uint32_t value,
                      std::size_t bytes)
{
    return expeditedDownload(index, subindex, littleEndian(value, bytes));
}

Sdo uploadRequest(std::uint16_t index, std::uint8_t subindex)
{
    Sdo s;
    s.command = SdoCommand::InitiateUploadRequest;
    s.index = index;
    s.subindex = subindex;
    return s;
}

Sdo downloadResponse(std::uint16_t index, std::uint8_t subindex)
{
    Sdo s = uploadRequest(index, subindex);
    s.command = SdoCommand::InitiateDownloadResponse;
    return s;
}

Sdo expeditedUploadResponse(std::uint16_t index, std::uint8_t subindex,
                            std::span<const std::uint8_t> data)
{
    Sdo s = expeditedDownload(index, subindex, data);
    s.command = SdoCommand::InitiateUploadResponse;
    return s;
}

Sdo expeditedUploadResponse(std::uint16_t index, std::uint8_t subindex, std::uint32_t value,
                            std::size_t bytes)
{
    return expeditedUploadResponse(index, subindex, littleEndian(value, bytes));
}

Sdo abortTransfer(std::uint16_t index, std::uint8_t subindex, std::uint32_t abortCode)
{
    Sdo s = uploadRequest(index, subindex);
    s.command = SdoCommand::Abort;
    s.abortCode = abortCode;
    return s;
}

std::uint32_t expeditedValue(const Sdo &sdo)
{
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < sdo.data.size() && i < 4; ++i)
        v |= static_cast<std::uint32_t>(sdo.data[i]) << (8 * i);
    return v;
}

Result<Bytes, DecodeError> encodeSdo(const Sdo &sdo)
{
    if (isBlockTransfer(sdo.command))
        return Bytes(sdo.blockRaw.begin(), sdo.blockRaw.end());
    const auto specifier = static_cast<std::uint8_t>(specifierOf(sdo.command) << kCsShift);
    ByteWriter w;
    if (isSegmentWithData(sdo.command)) {
        if (sdo.data.size() > 7)
            return badValue("segment carries " + std::to_string(sdo.data.size()) + " > 7 bytes");
        const auto n = static_cast<std::uint8_t>(7 - sdo.data.size());
        w.u8(static_cast<std::uint8_t>(specifier | (sdo.toggle ? kToggleBit : 0) | n << 1 |
                                       (sdo.last ? 1 : 0)));
        w.bytes(sdo.data);
    } else if (sdo.command == SdoCommand::UploadSegmentRequest ||
               sdo.command == SdoCommand::DownloadSegmentResponse) {
        w.u8(static_cast<std::uint8_t>(specifier | (sdo.toggle ? kToggleBit : 0)));
    } else {
        std::uint8_t byte0 = specifier;
        if (isInitiateWithData(sdo.command)) {
            if (sdo.expedited) {
                if (sdo.data.empty() || sdo.data.size() > 4)
                    return badValue("expedited transfer of " + std::to_string(sdo.data.size()) +
                                    " bytes (1..4)");
                if (!sdo.sizeIndicated && sdo.data.size() != 4)
                    return badValue("expedited transfer without size needs 4 bytes");
                byte0 = static_cast<std::uint8_t>(
                    byte0 | 0x02 | (sdo.sizeIndicated ? 0x01 | (4 - sdo.data.size()) << 2 : 0));
            } else if (sdo.sizeIndicated) {
                byte0 = static_cast<std::uint8_t>(byte0 | 0x01);
            }
        }
        w.u8(byte0).u16le(sdo.index).u8(sdo.subindex);
        if (sdo.command == SdoCommand::Abort)
            writeU32le(w, sdo.abortCode);
        else if (isInitiateWithData(sdo.command) && sdo.expedited)
            for (std::uint8_t b :
                 sdo.data) // byte by byte: w.bytes() trips GCC 12's -O3 -Wstringop-overflow
                w.u8(b);
        else if (isInitiateWithData(sdo.command) && sdo.sizeIndicated)
            writeU32le(w, sdo.size);
    }
    Bytes out = w.take();
    out.resize(kSdoSize, 0);
    return out;
}

Result<Sdo, DecodeError> decodeSdo(std::span<const std::uint8_t> data, Direction direction)
{
    if (data.size() < kSdoSize)
        return DecodeError{DecodeErrc::Truncated, data.size(), 0,
                           "SDO needs 8 data bytes (DLC 8), got " + std::to_string(data.size())};
    if (data.size() > kSdoSize)
        return DecodeError{DecodeErrc::TooLong, kSdoSize, 0, "a CAN frame holds 8 data bytes"};
    ByteReader r(data);
    const std::uint8_t byte0 = r.u8();
    const auto command = commandFor(cs(byte0), direction);
    if (!command)
        return DecodeError{DecodeErrc::UnexpectedCommand, 0, byte0,
                           "command specifier " + std::to_string(cs(byte0)) + " is not defined"};
    Sdo s;
    s.command = *command;
    if (isBlockTransfer(s.command)) {
        std::copy(data.begin(), data.end(), s.blockRaw.begin());
        return s;
    }
    s.toggle = (byte0 & kToggleBit) != 0;
    if (isSegmentWithData(s.command)) {
        const std::size_t unused = (byte0 >> 1) & 0x07;
        const auto seg = r.bytes(7 - unused);
        s.data.assign(seg.begin(), seg.end());
        s.last = (byte0 & 0x01) != 0;
        return s;
    }
    if (s.command == SdoCommand::UploadSegmentRequest ||
        s.command == SdoCommand::DownloadSegmentResponse)
        return s;
    s.toggle = false;
    s.index = r.u16le();
    s.subindex = r.u8();
    if (s.command == SdoCommand::Abort) {
        s.abortCode = readU32le(r);
        return s;
    }
    if (isInitiateWithData(s.command)) {
        s.expedited = (byte0 & 0x02) != 0;
        s.sizeIndicated = (byte0 & 0x01) != 0;
        if (s.expedited) {
            const std::size_t unused = s.sizeIndicated ? (byte0 >> 2) & 0x03 : 0;
            const auto d = r.bytes(4 - unused);
            s.data.assign(d.begin(), d.end());
        } else if (s.sizeIndicated) {
            s.size = readU32le(r);
        }
    }
    return s;
}

Result<CanFrame, DecodeError> toCanFrame(const Sdo &sdo, std::uint8_t node, Direction abortFrom)
{
    if (node == 0 || node > kMaxNodeId)
        return badValue("node id " + std::to_string(node) + " is not 1..127");
    auto bytes = encodeSdo(sdo);
    if (!bytes.ok())
        return bytes.error();
    const Direction direction =
        sdo.command == SdoCommand::Abort ? abortFrom : directionOf(sdo.command);
    const std::uint16_t id =
        direction == Direction::Request ? sdoRequestId(node) : sdoResponseId(node);
    return makeCanFrame(id, *bytes);
}

Result<SdoMessage, DecodeError> fromCanFrame(const CanFrame &frame)
{
    const auto channel =
        frame.extended || frame.rtr || frame.errorFrame ? std::nullopt : sdoChannel(frame.id);
    if (!channel)
        return DecodeError{DecodeErrc::UnexpectedCommand, 0, 0,
                           "COB-ID " + std::to_string(frame.id) +
                               " is not an SDO channel (0x581..0x5FF, 0x601..0x67F)"};
    auto sdo = decodeSdo(frame.payload(), channel->direction);
    if (!sdo.ok())
        return sdo.error();
    return SdoMessage{*channel, *sdo};
}

} // namespace vt::dev::canopen
