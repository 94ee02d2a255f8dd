// CanFrame: one classic CAN frame and its 16-byte image, the Linux `struct can_frame` layout that
// CanLink moves (SocketCAN raw sockets read and write exactly this): can_id (u32, host byte
// order, with the EFF/RTR/ERR flags in the top bits), len (u8), 3 padding bytes (zero), data[8].
// A plain value; any thread.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <cstdint>
#include <optional>

namespace vt::link {

struct CanFrame
{
    static constexpr qsizetype kImageSize = 16;
    static constexpr qsizetype kMaxData = 8;
    static constexpr std::uint32_t kStandardIdMask = 0x7FF;
    static constexpr std::uint32_t kExtendedIdMask = 0x1FFFFFFF;

    std::uint32_t id = 0;  // identifier without flags: 11 bits, or 29 bits when extended
    bool extended = false; // CAN_EFF_FLAG
    bool remote = false;   // CAN_RTR_FLAG
    bool error = false;    // CAN_ERR_FLAG (error frames from the controller)
    QByteArray data;       // 0..8 bytes

    // False for an identifier too wide for its format or more than 8 data bytes.
    bool isValid() const;
    // The 16-byte image; only meaningful for a valid frame.
    QByteArray toImage() const;
    // nullopt unless exactly 16 bytes with len ≤ 8.
    static std::optional<CanFrame> fromImage(QByteArrayView image);

    friend bool operator==(const CanFrame &, const CanFrame &) = default;
};

} // namespace vt::link
