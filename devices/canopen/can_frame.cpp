#include "canopen/can_frame.h"

#include "core/byte_reader.h"
#include "core/byte_writer.h"
#include "core/hex.h"

#include <algorithm>
#include <bit>

namespace vt::dev::canopen {
namespace {

constexpr std::uint32_t kEffFlag = 0x80000000u;
constexpr std::uint32_t kRtrFlag = 0x40000000u;
constexpr std::uint32_t kErrFlag = 0x20000000u;

// can_id is in host byte order: the kernel hands over the struct as it sits in memory.
std::uint32_t readHostU32(ByteReader &r)
{
    if constexpr (std::endian::native == std::endian::little) {
        const std::uint32_t low = r.u16le();
        const std::uint32_t high = r.u16le();
        return high << 16 | low;
    } else {
        return r.u32be();
    }
}

void writeHostU32(ByteWriter &w, std::uint32_t v)
{
    if constexpr (std::endian::native == std::endian::little)
        w.u16le(static_cast<std::uint16_t>(v)).u16le(static_cast<std::uint16_t>(v >> 16));
    else
        w.u32be(v);
}

DecodeError bad(DecodeErrc code, std::size_t offset, std::string detail)
{
    return DecodeError{code, offset, 0, std::move(detail)};
}

} // namespace

CanFrame makeCanFrame(std::uint32_t id, std::span<const std::uint8_t> payload)
{
    CanFrame f;
    f.id = id;
    f.extended = id > kMaxStandardId;
    f.dlc = static_cast<std::uint8_t>(std::min<std::size_t>(payload.size(), 8));
    std::copy_n(payload.begin(), f.dlc, f.data.begin());
    return f;
}

std::array<std::uint8_t, kSocketCanFrameSize> toSocketCan(const CanFrame &frame)
{
    // Error frames carry error-class bits in all 29 id bits.
    std::uint32_t id =
        frame.id & (frame.extended || frame.errorFrame ? kMaxExtendedId : kMaxStandardId);
    if (frame.extended)
        id |= kEffFlag;
    if (frame.rtr)
        id |= kRtrFlag;
    if (frame.errorFrame)
        id |= kErrFlag;
    ByteWriter w;
    writeHostU32(w, id);
    w.u8(frame.dlc <= 8 ? frame.dlc : 8).u8(0).u8(0).u8(0);
    w.bytes(frame.data);
    std::array<std::uint8_t, kSocketCanFrameSize> out{};
    std::copy_n(w.data().begin(), kSocketCanFrameSize, out.begin());
    return out;
}

Result<CanFrame, DecodeError> fromSocketCan(std::span<const std::uint8_t> bytes)
{
    ByteReader r(bytes);
    const std::uint32_t canId = readHostU32(r);
    const std::uint8_t len = r.u8();
    r.skip(3); // __pad, __res0, len8_dlc (CAN FD / DLC 9..15 extension, unused here)
    const auto data = r.bytes(8);
    if (r.failed())
        return bad(DecodeErrc::Truncated, r.failOffset(), "struct can_frame has 16 bytes");
    if (!r.atEnd())
        return bad(DecodeErrc::TooLong, kSocketCanFrameSize, "struct can_frame has 16 bytes");
    if (len > 8)
        return bad(DecodeErrc::BadLength, 4, "len " + std::to_string(len) + " > 8");
    CanFrame f;
    f.extended = (canId & kEffFlag) != 0;
    f.rtr = (canId & kRtrFlag) != 0;
    f.errorFrame = (canId & kErrFlag) != 0;
    f.id = canId & kMaxExtendedId;
    if (!f.extended && f.id > kMaxStandardId && !f.errorFrame)
        return bad(DecodeErrc::BadValue, 0, "standard id " + std::to_string(f.id) + " > 0x7FF");
    f.dlc = len;
    std::copy(data.begin(), data.end(), f.data.begin());
    return f;
}

Result<CanFrame, DecodeError> parseCandump(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\n' ||
                             text.back() == '\r'))
        text.remove_suffix(1);
    const std::size_t hash = text.find('#');
    if (hash == std::string_view::npos || hash == 0 || hash > 8)
        return bad(DecodeErrc::BadValue, 0, "expected <id>#<data>");
    CanFrame f;
    for (char c : text.substr(0, hash)) {
        const int n = hexDigitValue(c);
        if (n < 0)
            return bad(DecodeErrc::BadValue, 0, "id is not hex");
        f.id = f.id << 4 | static_cast<std::uint32_t>(n);
    }
    f.extended = hash > 3;
    if (!f.extended && f.id > kMaxStandardId)
        return bad(DecodeErrc::BadValue, 0, "standard id > 0x7FF");
    if (f.id > kMaxExtendedId)
        return bad(DecodeErrc::BadValue, 0, "extended id > 0x1FFFFFFF");
    std::string_view data = text.substr(hash + 1);
    if (!data.empty() && (data.front() == 'R' || data.front() == 'r')) {
        f.rtr = true;
        data.remove_prefix(1);
        if (!data.empty()) {
            const auto dlc = parseHex(data);
            if (!dlc.ok() || dlc->size() != 1 || dlc->front() > 8)
                return bad(DecodeErrc::BadValue, hash + 2, "RTR length must be 0..8");
            f.dlc = dlc->front();
        }
        return f;
    }
    if (data.size() % 2 != 0)
        return bad(DecodeErrc::BadValue, hash + 1, "odd number of hex digits");
    const auto bytes = parseHex(data);
    if (!bytes.ok())
        return bad(DecodeErrc::BadValue, hash + 1 + bytes.error().position, bytes.error().reason);
    if (bytes->size() > 8)
        return bad(DecodeErrc::BadLength, hash + 1,
                   std::to_string(bytes->size()) + " data bytes > 8");
    f.dlc = static_cast<std::uint8_t>(bytes->size());
    std::copy(bytes->begin(), bytes->end(), f.data.begin());
    return f;
}

std::string formatCandump(const CanFrame &frame)
{
    std::string id = toHex(std::array<std::uint8_t, 4>{static_cast<std::uint8_t>(frame.id >> 24),
                                                       static_cast<std::uint8_t>(frame.id >> 16),
                                                       static_cast<std::uint8_t>(frame.id >> 8),
                                                       static_cast<std::uint8_t>(frame.id)},
                           '\0');
    if (!frame.extended)
        id = id.substr(5);
    if (frame.rtr)
        return id + "#R" +
               (frame.dlc ? std::string(1, static_cast<char>('0' + std::min<int>(frame.dlc, 8)))
                          : "");
    return id + "#" + toHex(frame.payload(), '\0');
}

} // namespace vt::dev::canopen
