#include "can_frame.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <linux/can.h>

namespace vt::link {

static_assert(sizeof(can_frame) == CanFrame::kImageSize, "struct can_frame is 16 bytes");
static_assert(offsetof(can_frame, data) == 8, "can_frame payload starts at byte 8");

bool CanFrame::isValid() const
{
    const std::uint32_t mask = extended || error ? kExtendedIdMask : kStandardIdMask;
    return (id & ~mask) == 0 && data.size() <= kMaxData;
}

QByteArray CanFrame::toImage() const
{
    can_frame frame;
    std::memset(&frame, 0, sizeof frame);
    frame.can_id = id & (extended || error ? CAN_EFF_MASK : CAN_SFF_MASK);
    if (extended)
        frame.can_id |= CAN_EFF_FLAG;
    if (remote)
        frame.can_id |= CAN_RTR_FLAG;
    if (error)
        frame.can_id |= CAN_ERR_FLAG;
    const qsizetype n = std::min(data.size(), kMaxData);
    frame.len = static_cast<__u8>(n);
    if (n > 0)
        std::memcpy(frame.data, data.constData(), static_cast<size_t>(n));
    return QByteArray(reinterpret_cast<const char *>(&frame), sizeof frame);
}

std::optional<CanFrame> CanFrame::fromImage(QByteArrayView image)
{
    if (image.size() != kImageSize)
        return std::nullopt;
    can_frame frame;
    std::memcpy(&frame, image.data(), sizeof frame);
    if (frame.len > kMaxData)
        return std::nullopt;
    CanFrame f;
    f.extended = (frame.can_id & CAN_EFF_FLAG) != 0;
    f.remote = (frame.can_id & CAN_RTR_FLAG) != 0;
    f.error = (frame.can_id & CAN_ERR_FLAG) != 0;
    // Error frames carry their error class in the 29 identifier bits.
    f.id = frame.can_id & (f.extended || f.error ? CAN_EFF_MASK : CAN_SFF_MASK);
    f.data = QByteArray(reinterpret_cast<const char *>(frame.data), frame.len);
    return f;
}

} // namespace vt::link
