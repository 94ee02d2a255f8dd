// The master side of every protocol, without Qt and without I/O: a ProtocolAdapter turns "read
// these rows of module M" / "write this value" into transactions, encodes each transaction's
// request bytes and recognises its reply in the bytes the link delivers. The session (model/)
// owns the queue, the timers and the retries; an adapter owns only framing state.
// Owner: one session; single-threaded.
#pragma once

#include "core/byte_writer.h"
#include "core/link_protocol.h"
#include "core/local_text.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vt::dev::access {

enum class TransactionKind { Identify, Read, Write, Raw };

// One request/response exchange on the wire.
struct Transaction
{
    TransactionKind kind = TransactionKind::Read;
    int module = 0; // module address (HCS SADR / unit id, HART poll address, CAN node)
    std::vector<const ParamMeta *> rows; // Read: the rows answered by this exchange, in wire order;
                                         // Write: exactly one row
    std::vector<RawValue> values;        // Write: the value to write (one)
    int step = 0;                        // Identify: which of the adapter's identify exchanges
                                         // (HCS: 0 = Vers (ID 0), 1 = E00 (ID 95))
    Bytes raw;                // Raw: bytes to send as they are (the inspector's composer)
    bool expectsReply = true; // Raw: false for a frame sent without waiting

    static Transaction read(int module, std::vector<const ParamMeta *> rows)
    {
        return {TransactionKind::Read, module, std::move(rows), {}, 0, {}, true};
    }
    static Transaction write(int module, const ParamMeta &row, RawValue value)
    {
        return {TransactionKind::Write, module, {&row}, {std::move(value)}, 0, {}, true};
    }
    static Transaction identify(int module, int step = 0)
    {
        return {TransactionKind::Identify, module, {}, {}, step, {}, true};
    }
    static Transaction rawFrame(int module, Bytes bytes, bool expectsReply = true)
    {
        return {TransactionKind::Raw, module, {}, {}, 0, std::move(bytes), expectsReply};
    }
};

enum class ReplyStatus {
    Ok, // values hold one entry per row (Read), the echoed value (Write), identity (Identify)
    DeviceException, // the device refused: code + text
    Mismatch, // a well-formed frame that does not answer this request (other unit, other ID…)
    // A frame that belongs to this exchange but does not end it: a cyclic link's image that does
    // not show the answer yet, a gateway's write confirmation. The session sends Reply::next —
    // at once, or after one bus cycle when Reply::nextAfterCycle — within the same attempt.
    Progress,
};

struct Identity
{
    int versRaw = -1;                     // HCS: ID 0, raw = version × 100
    int mode = -1;                        // HCS: E00
    std::uint16_t manufacturer = 0;       // HART command 0
    std::uint16_t expandedDeviceType = 0; // HART command 0
    std::uint32_t deviceId = 0;           // HART command 0
    std::uint32_t capability = 0;         // DSP-408 db_Capability (ED1/SD1 manual §4.8.7)
    std::uint16_t deviceProfile = 0;      // CANopen 0x1000 bits 15..0 (CiA 301): 408 = DSP-408
    LocalText text; // for people, in both languages ("HART rev 7, … device id 0x000123")
};

struct Reply
{
    ReplyStatus status = ReplyStatus::Ok;
    std::vector<RawValue> values;
    Identity identity;
    int exceptionCode = 0;
    LocalText exceptionText;
    Bytes frame; // the reply as it came off the wire
    // Progress: the bytes to send next, and whether to wait a bus cycle before sending them.
    Bytes next;
    bool nextAfterCycle = false;
};

// For feed(): several frames may arrive in one chunk. Keeps the first reply that answers the
// request, else the first Mismatch (so the session can log it); true once `result` answers.
inline bool offerReply(std::optional<Reply> &result, Reply reply)
{
    if (reply.status != ReplyStatus::Mismatch || !result)
        result = std::move(reply);
    return result->status != ReplyStatus::Mismatch;
}

class ProtocolAdapter
{
public:
    virtual ~ProtocolAdapter() = default;

    virtual LinkProtocol protocol() const = 0;

    // The fewest transactions the device allows for reading `rows` of `module` (HCS: ≤ 8
    // consecutive IDs per request; gaps are not read). Rows the protocol cannot address are
    // left out; the caller compares.
    virtual std::vector<Transaction> planRead(int module,
                                              std::span<const ParamMeta *const> rows) const = 0;
    // One transaction writing `value` to `row`: every protocol writes one row per exchange;
    // encode() refuses a value or row the protocol cannot carry.
    Transaction planWrite(int module, const ParamMeta &row, const RawValue &value) const
    {
        return Transaction::write(module, row, value);
    }
    // What identifies the module (HCS: Vers and E00; HART: command 0).
    virtual std::vector<Transaction> planIdentify(int module) const = 0;

    // Request bytes for one attempt of `t` (an adapter may change bytes between attempts: the
    // node image toggles TADR, Modbus TCP numbers transactions). Empty on an encoding error.
    virtual Bytes encode(const Transaction &t) = 0;
    // Upper bound of the reply's length in bytes, for the session's timeout.
    virtual std::size_t expectedReplyBytes(const Transaction &t) const = 0;

    // Feeds bytes from the link while `t` is outstanding. Returns the reply once a whole frame
    // answering `t` (or a device exception) has arrived; frames that do not answer `t` come back
    // as Mismatch and the session keeps waiting. Garbage is dropped silently.
    virtual std::optional<Reply> feed(std::span<const std::uint8_t> bytes,
                                      const Transaction &t) = 0;
    // Drops buffered bytes (after a timeout, before a retry, after reconnect).
    virtual void resetFraming() = 0;
    // The link saw the line quiet for the protocol's silent interval: buffered bytes that are no
    // frame yet never will be (Modbus RTU, Modbus over Serial Line §2.5.1.1). `onTheWire` is the
    // transaction whose answer is awaited (nullptr: none). Default: nothing.
    virtual void lineQuiet(const Transaction *onTheWire) { (void)onTheWire; }
};

} // namespace vt::dev::access
