// HCS modules and the Wandfluh ED1 over CAN as a CANopen SDO client (ARCHITECTURE.md "CAN"; CiA
// 301 §7.2.4.3): one expedited upload (read) or download (write) per parameter on the default SDO
// channel, request 0x600 + node, response 0x580 + node, carried as the 16-byte SocketCAN
// `struct can_frame` images the CAN link moves (canopen/can_frame.h toSocketCan / fromSocketCan).
// Owner: one session; single-threaded.
#pragma once

#include "access/transaction.h"
#include "canopen/sdo.h"
#include "dict/device_protocol.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace vt::dev::access {

enum class CanopenProfile {
    Hcs,    // manufacturer objects 0x2000 + ID, sub 0 (or the row's canopen object), 16-bit words
    Dsp408, // the rows' canopen objects (CiA 408: 0x6040, 0x6041, …), the width of the row's type
};

// The objects a device family has: HCS 0x2000 + ID, the others their CiA 408 objects.
CanopenProfile canopenProfileOf(DeviceProtocol device);

// The object of a row: the dictionary's `canopen` field; HCS rows without one: 0x2000 + ID, sub 0.
// nullopt when the row has neither (such rows cannot be read or written over CANopen).
std::optional<CanObject> canopenObjectOf(const ParamMeta &row, CanopenProfile profile);

class CanopenAdapter : public ProtocolAdapter
{
public:
    static constexpr std::uint16_t kHcsBase = 0x2000;
    static constexpr std::uint16_t kDeviceTypeObject = 0x1000; // CiA 301 §7.5.2.1
    // CiA 408's device capability object, where DSP-408's db_Capability lives on CANopen
    // (an assumption the dictionary does not make: docs/protocol-notes/ed1-online.md).
    static constexpr std::uint16_t kCapabilityObject = 0x605F;

    explicit CanopenAdapter(CanopenProfile profile) : m_profile(profile) {}

    LinkProtocol protocol() const override { return LinkProtocol::Canopen; }

    // One upload per readable row with an object; rows without one are left out.
    std::vector<Transaction> planRead(int module,
                                      std::span<const ParamMeta *const> rows) const override;
    // HCS: step 0 uploads 0x2000 (Vers, ID 0), step 1 0x2000 + 95 (E00). DSP-408: step 0 uploads
    // 0x1000 "device type" (CiA 301: profile number in bits 15..0, 408 → Identity::deviceProfile);
    // step 1 the capability object (kCapabilityObject, → Identity::capability). The ED1/SD1
    // manual names db_Capability (§4.8.7) but no CANopen object for it: a device without the
    // object aborts, and that step then answers Ok without a capability.
    std::vector<Transaction> planIdentify(int module) const override;

    // One 16-byte image. Empty for a node outside 1..127, a row without object, a text value or
    // a value the object cannot hold.
    Bytes encode(const Transaction &t) override;
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    // Cuts the stream into 16-byte images. A frame answers `t` when it is a standard data frame
    // on 0x580 + node whose SDO names the requested index and sub-index: an expedited upload
    // response (values little-endian, CiA 301 §7.1.3.1), a download confirmation or an abort
    // (DeviceException, canopen::abortCodeText). Other frames on the bus are Mismatch.
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;

private:
    struct Access
    {
        CanObject object;
        std::size_t width = 2; // bytes of the value on the wire
    };
    std::optional<Access> accessOf(const Transaction &t) const;
    std::optional<canopen::Sdo> requestOf(const Transaction &t) const;
    Reply sdoReply(const canopen::Sdo &sdo, const Transaction &t) const;
    double valueFromBits(const Transaction &t, std::uint32_t bits) const;

    CanopenProfile m_profile;
    Bytes m_buffer; // bytes of an image not yet complete
};

} // namespace vt::dev::access
