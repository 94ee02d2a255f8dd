#include "hart/frame.h"

#include "core/byte_reader.h"
#include "core/hex.h"

#include <string>

namespace vt::dev::hart {
namespace {

constexpr std::uint8_t kLongFrameBit = 0x80;
constexpr std::uint8_t kMasterBit = 0x80;
constexpr std::uint8_t kBurstBit = 0x40;

std::size_t addressSize(std::uint8_t delimiter)
{
    return (delimiter & kLongFrameBit) ? 5 : 1;
}

std::size_t expansionCount(std::uint8_t delimiter)
{
    return static_cast<std::size_t>((delimiter >> 5) & 0x03);
}

DecodeError badValue(std::string detail)
{
    return DecodeError{DecodeErrc::BadValue, 0, 0, std::move(detail)};
}

} // namespace

Address shortAddress(std::uint8_t pollAddress, bool primaryMaster)
{
    Address a;
    a.primaryMaster = primaryMaster;
    a.pollAddress = pollAddress;
    return a;
}

Address longAddress(std::uint16_t expandedDeviceType, std::uint32_t deviceId, bool primaryMaster)
{
    Address a;
    a.isLong = true;
    a.primaryMaster = primaryMaster;
    a.expandedDeviceType = static_cast<std::uint16_t>(expandedDeviceType & kMaxLongDeviceType);
    a.deviceId = deviceId & kMaxDeviceId;
    return a;
}

Frame makeRequest(const Address &address, std::uint8_t command, Bytes data)
{
    Frame f;
    f.type = FrameType::Stx;
    f.address = address;
    f.command = command;
    f.data = std::move(data);
    return f;
}

Frame makeResponse(const Address &address, std::uint8_t command, std::uint8_t responseCode,
                   std::uint8_t deviceStatus, Bytes data)
{
    Frame f = makeRequest(address, command, std::move(data));
    f.type = FrameType::Ack;
    f.responseCode = responseCode;
    f.deviceStatus = deviceStatus;
    return f;
}

Address decodeAddress(std::span<const std::uint8_t> bytes, bool isLong)
{
    ByteReader r(bytes);
    Address a;
    const std::uint8_t first = r.u8();
    a.isLong = isLong;
    a.primaryMaster = (first & kMasterBit) != 0;
    a.burst = (first & kBurstBit) != 0;
    if (isLong) {
        a.expandedDeviceType = static_cast<std::uint16_t>((first & 0x3F) << 8 | r.u8());
        const std::uint32_t high = r.u8();
        a.deviceId = high << 16 | r.u16be();
    } else {
        a.pollAddress = first & kMaxPollAddress;
    }
    return a;
}

std::uint8_t delimiterOf(const Frame &frame)
{
    const auto expansion = static_cast<unsigned>(frame.expansion.size() & 0x03u);
    return static_cast<std::uint8_t>((frame.address.isLong ? kLongFrameBit : 0u) | expansion << 5 |
                                     (frame.physicalLayer & 0x03u) << 3 |
                                     static_cast<unsigned>(frame.type));
}

bool isValidDelimiter(std::uint8_t delimiter)
{
    const auto type = delimiter & 0x07;
    return type == 1 || type == 2 || type == 6;
}

std::size_t headerSize(std::uint8_t delimiter)
{
    return addressSize(delimiter) + expansionCount(delimiter) + 1;
}

std::uint8_t checksum(std::span<const std::uint8_t> bytes)
{
    std::uint8_t x = 0;
    for (std::uint8_t b : bytes)
        x ^= b;
    return x;
}

Result<Bytes, DecodeError> encodeFrame(const Frame &frame)
{
    const Address &a = frame.address;
    if (frame.expansion.size() > kMaxExpansionBytes)
        return badValue(std::to_string(frame.expansion.size()) + " expansion bytes > 3");
    if (frame.physicalLayer > 3)
        return badValue("physical layer type > 3");
    if (!a.isLong && a.pollAddress > kMaxPollAddress)
        return badValue("poll address " + std::to_string(a.pollAddress) + " > 63");
    if (a.isLong && a.expandedDeviceType > kMaxLongDeviceType)
        return badValue("device type " + hexWord(a.expandedDeviceType) + " has more than 14 bits");
    if (a.isLong && a.deviceId > kMaxDeviceId)
        return badValue("device id " + std::to_string(a.deviceId) + " has more than 24 bits");
    if (frame.preambles > kMaxPreambles)
        return badValue(std::to_string(frame.preambles) + " preambles > 255");
    const std::size_t count = frame.data.size() + (frame.isResponse() ? 2 : 0);
    if (count > kMaxByteCount)
        return badValue("byte count " + std::to_string(count) + " > 255");

    ByteWriter w;
    for (std::size_t i = 0; i < frame.preambles; ++i)
        w.u8(kPreamble);
    const std::size_t start = frame.preambles;
    w.u8(delimiterOf(frame));
    const auto bits =
        static_cast<std::uint8_t>((a.primaryMaster ? kMasterBit : 0) | (a.burst ? kBurstBit : 0));
    if (a.isLong) {
        w.u8(static_cast<std::uint8_t>(bits | (a.expandedDeviceType >> 8)));
        w.u8(static_cast<std::uint8_t>(a.expandedDeviceType));
        w.u8(static_cast<std::uint8_t>(a.deviceId >> 16));
        w.u16be(static_cast<std::uint16_t>(a.deviceId));
    } else {
        w.u8(static_cast<std::uint8_t>(bits | a.pollAddress));
    }
    w.bytes(frame.expansion);
    w.u8(frame.command);
    w.u8(static_cast<std::uint8_t>(count));
    if (frame.isResponse())
        w.u8(frame.responseCode).u8(frame.deviceStatus);
    w.bytes(frame.data);
    Bytes out = w.take();
    out.push_back(checksum(std::span<const std::uint8_t>(out).subspan(start)));
    return out;
}

Result<Frame, DecodeError> decodeFrame(std::span<const std::uint8_t> bytes)
{
    Frame f;
    f.preambles = 0;
    for (std::uint8_t b : bytes) {
        if (b != kPreamble)
            break;
        ++f.preambles;
    }
    if (f.preambles > kMaxPreambles)
        return DecodeError{DecodeErrc::BadLength, kMaxPreambles, 0,
                           std::to_string(f.preambles) + " preambles > 255"};
    ByteReader r(bytes);
    r.skip(f.preambles);
    const std::size_t start = r.offset();
    const std::uint8_t delimiter = r.u8();
    if (r.failed())
        return DecodeError{DecodeErrc::Truncated, r.failOffset(), 0,
                           "no delimiter after the preambles"};
    if (!isValidDelimiter(delimiter))
        return DecodeError{DecodeErrc::BadValue, start, delimiter,
                           "delimiter " + hexByte(delimiter) + " has no frame type 1, 2 or 6"};
    f.type = static_cast<FrameType>(delimiter & 0x07);
    f.physicalLayer = static_cast<std::uint8_t>((delimiter >> 3) & 0x03);

    f.address = decodeAddress(r.bytes(addressSize(delimiter)), (delimiter & kLongFrameBit) != 0);
    const auto expansion = r.bytes(expansionCount(delimiter));
    f.expansion.assign(expansion.begin(), expansion.end());
    f.command = r.u8();
    const std::size_t countAt = r.offset();
    const std::uint8_t count = r.u8();
    if (r.failed())
        return DecodeError{DecodeErrc::Truncated, r.failOffset(), 0, "frame header incomplete"};
    std::size_t dataBytes = count;
    if (f.isResponse()) {
        if (count < 2)
            return DecodeError{DecodeErrc::BadLength, countAt, 0,
                               "response byte count " + std::to_string(count) +
                                   " < 2 status bytes"};
        f.responseCode = r.u8();
        f.deviceStatus = r.u8();
        dataBytes -= 2;
    }
    const auto data = r.bytes(dataBytes);
    f.data.assign(data.begin(), data.end());
    const std::size_t checksumAt = r.offset();
    const std::uint8_t sum = r.u8();
    if (r.failed())
        return DecodeError{DecodeErrc::Truncated, r.failOffset(), 0,
                           "byte count " + std::to_string(count) + " runs past the end"};
    const std::uint8_t expected = checksum(bytes.subspan(start, checksumAt - start));
    if (sum != expected)
        return DecodeError{DecodeErrc::BadChecksum, checksumAt, sum,
                           "checksum " + hexByte(sum) + ", computed " + hexByte(expected)};
    if (!r.atEnd())
        return DecodeError{DecodeErrc::TooLong, r.offset(), 0,
                           std::to_string(bytes.size() - r.offset()) + " bytes after the checksum"};
    return f;
}

} // namespace vt::dev::hart
