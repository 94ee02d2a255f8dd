#include "sim/canopen_dsp408_objects.h"

namespace vt::dev::sim {

SdoAbort sdoAbortFor(ParamErrc error)
{
    switch (error) {
    case ParamErrc::Unknown: return {sdo_abort::kNoObject};
    case ParamErrc::NotReadable: return {sdo_abort::kWriteOnly};
    case ParamErrc::ReadOnly: return {sdo_abort::kReadOnly};
    case ParamErrc::BelowMin: return {sdo_abort::kValueTooLow};
    case ParamErrc::AboveMax: return {sdo_abort::kValueTooHigh};
    case ParamErrc::WrongWidth: return {sdo_abort::kLengthMismatch};
    case ParamErrc::InvalidValue: return {sdo_abort::kInvalidValue};
    case ParamErrc::WrongState: return {sdo_abort::kDeviceState};
    }
    return {sdo_abort::kGeneral};
}

Dsp408Objects::Dsp408Objects(Dsp408Device &device) : m_device(device)
{
}

Result<const ParamMeta *, SdoAbort> Dsp408Objects::find(std::uint16_t index,
                                                        std::uint8_t subindex) const
{
    bool indexSeen = false;
    for (const ParamMeta &meta : m_device.params().dictionary().params) {
        if (!meta.canopen || meta.canopen->index != index)
            continue;
        if (!m_device.params().find(meta.name))
            continue; // not implemented (access n / x)
        indexSeen = true;
        if (meta.canopen->sub == subindex)
            return &meta;
    }
    return SdoAbort{indexSeen ? sdo_abort::kNoSubindex : sdo_abort::kNoObject};
}

Result<ObjectValue, SdoAbort> Dsp408Objects::read(std::uint16_t index, std::uint8_t subindex)
{
    if (index == 0x1000)
        return subindex == 0 ? Result<ObjectValue, SdoAbort>(ObjectValue{kDeviceType, 4})
                             : Result<ObjectValue, SdoAbort>(SdoAbort{sdo_abort::kNoSubindex});
    auto meta = find(index, subindex);
    if (!meta.ok())
        return meta.error();
    double raw = 0;
    if (auto error = m_device.read(**meta, raw))
        return sdoAbortFor(*error);
    return ObjectValue{toWireBits(**meta, raw), wireBytes((*meta)->type)};
}

std::optional<SdoAbort> Dsp408Objects::write(std::uint16_t index, std::uint8_t subindex,
                                             std::uint32_t bits, std::size_t size)
{
    if (index == 0x1000)
        return subindex == 0 ? SdoAbort{sdo_abort::kReadOnly} : SdoAbort{sdo_abort::kNoSubindex};
    auto found = find(index, subindex);
    if (!found.ok())
        return found.error();
    const ParamMeta &meta = **found;
    if (!meta.writable())
        return SdoAbort{sdo_abort::kReadOnly};
    const std::size_t width = wireBytes(meta.type);
    if (auto abort = lengthAbort(size, width))
        return abort;
    // Unsized (s = 0): the low bytes of the 4 carry the value (fromWireBits reads only those).
    if (auto error = m_device.write(meta, fromWireBits(meta, bits)))
        return sdoAbortFor(*error);
    return std::nullopt;
}

} // namespace vt::dev::sim
