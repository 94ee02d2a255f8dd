// The CiA 408 objects of a simulated ED1/SD1 for the CANopen SDO server: every dictionary row with
// a `canopen` field (wandfluh-ed1: 0x6040 control word, 0x6041 status word, 0x6042 device mode,
// 0x6043 control mode, 0x604F local, 0x6600/1 set value, 0x6601/1 actual value; ARCHITECTURE.md
// "CAN"), plus CiA 301 0x1000 "device type" (profile 408). Accesses go through Dsp408Device, so
// PKW, PZD and SDO see one device; refusals become CiA 301 abort codes.
// Owner: whoever builds the simulator; single-threaded. The device must outlive this object.
#pragma once

#include "sim/dsp408_device.h"
#include "sim/object_dictionary.h"

namespace vt::dev::sim {

class Dsp408Objects : public ObjectDictionary
{
public:
    // CiA 301 §7.5.2.1 object 0x1000: bits 15..0 = device profile number (408 = 0x0198).
    static constexpr std::uint32_t kDeviceType = 408;

    explicit Dsp408Objects(Dsp408Device &device);

    Result<ObjectValue, SdoAbort> read(std::uint16_t index, std::uint8_t subindex) override;
    std::optional<SdoAbort> write(std::uint16_t index, std::uint8_t subindex, std::uint32_t bits,
                                  std::size_t size) override;

private:
    // The row of index/sub, or the abort code: no object, or the object without that sub-index.
    Result<const ParamMeta *, SdoAbort> find(std::uint16_t index, std::uint8_t subindex) const;

    Dsp408Device &m_device;
};

// CiA 301 abort code for a device refusal (write-only, read-only, range, state, …).
SdoAbort sdoAbortFor(ParamErrc error);

} // namespace vt::dev::sim
