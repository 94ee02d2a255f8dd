// The Wandfluh SD7 over HART-7 as the primary master (ARCHITECTURE.md "HART"; HART-7 manual
// §2.3, §4.4.1, §5.1.1): command 0 by poll address identifies a device and yields its unique id;
// every later request is a long frame to that id, one command 128..133 per parameter.
// Owner: one session; single-threaded.
#pragma once

#include "access/transaction.h"
#include "hart/deframer.h"
#include "hart/device_specific.h"
#include "hart/frame.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>

namespace vt::dev::access {

struct HartAdapterOptions
{
    bool primaryMaster = true; // HART-7 manual §2.3 "Address": the master bit
    // HART-7 manual §2.3: "three or more" preambles; raised to the device's minimum from command 0.
    std::size_t requestPreambles = 5;
    // Upper bound of the preambles a device puts before its answer, for expectedReplyBytes only
    // (command 0 byte 12 gives the device's minimum, HART-7 manual §5.1.1; the SD7 sends 5).
    std::size_t maxResponsePreambles = 20;
};

// The HART value type of a dictionary row; nullopt for text rows (no command 128..133 carries
// them).
std::optional<hart::ValueType> hartValueType(const ParamMeta &row);

class HartAdapter : public ProtocolAdapter
{
public:
    HartAdapter() = default;
    explicit HartAdapter(HartAdapterOptions options) : m_options(options) {}

    LinkProtocol protocol() const override { return LinkProtocol::Hart; }

    // One command 128/130/132 per readable row with IND, PNU and instance of one byte each and a
    // numeric type (HART-7 manual §4.4.1); one universal command for the `hart` rows it carries
    // (hart_universal_rows.h); other rows are left out.
    std::vector<Transaction> planRead(int module,
                                      std::span<const ParamMeta *const> rows) const override;
    // Command 129/131/133 by the row's type.
    // Command 0 in a short frame to poll address `module` (0..63).
    std::vector<Transaction> planIdentify(int module) const override;

    // Reads and writes go in a long frame to the unique id command 0 reported for `module`.
    // Decision: before the module has been identified (or after forget()) they cannot be
    // addressed and encode() returns no bytes (an encoding error for the session), as it does
    // for an out-of-range value, a text value or a row without IND / PNU.
    Bytes encode(const Transaction &t) override;
    // Preambles + delimiter + address + command + byte count + 2 status bytes + data + checksum.
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    // Whole frames from the de-framer (preambles skipped, bad checksums dropped). An ACK answers
    // `t` when address (poll address or unique id), master bit and command match. A response
    // code that is an error (hart::isErrorResponse, including the communication-error byte) is a
    // DeviceException with its text; a warning code gives Ok with the code and text attached in
    // exceptionCode / exceptionText.
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;

    // The long-frame address learned from command 0 of `module`; nullopt before identification.
    std::optional<hart::Address> longAddressOf(int module) const;
    // Use a known device without command 0 (a saved session) / forget it (device replaced).
    void setLongAddress(int module, hart::Address address, std::size_t requestPreambles = 5);
    void forget(int module) { m_devices.erase(module); }

private:
    struct Device
    {
        hart::Address address;
        std::size_t requestPreambles = 5;
        // The last data of command 13 (tag, descriptor, date): command 18 writes all three, so
        // writing one of them sends the others as the device last reported them (§5.1.16).
        Bytes tagDescriptorDate;
        // The last data of command 48, sent back with the next command 48 (§5.1.22).
        Bytes additionalStatus;
    };

    std::optional<Reply> frameReply(const hart::Frame &frame, const Transaction &t);
    Reply identityReply(const hart::Frame &frame, const Transaction &t);
    Reply parameterReply(const hart::Frame &frame, const Transaction &t) const;
    Bytes encodeUniversal(const Transaction &t, const Device &device);
    Reply universalReply(const hart::Frame &frame, const Transaction &t);

    HartAdapterOptions m_options;
    std::map<int, Device> m_devices; // by module (poll address)
    hart::Deframer m_deframer;
};

} // namespace vt::dev::access
