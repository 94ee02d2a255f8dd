#include "hart_adapter.h"

#include "access/hart_universal_rows.h"
#include "access/wire_value.h"
#include "hart/texts.h"
#include "hart/universal.h"

#include <algorithm>
#include <variant>

namespace vt::dev::access {

namespace {

constexpr std::uint8_t kReadUniqueIdentifier = 0; // HART-7 manual §5.1.1
// HART-7 manual §5.1.1: the HART 7 command 0 answer has 22 data bytes.
constexpr std::size_t kCommand0Bytes = 22;
constexpr std::size_t kParamRefBytes = 3; // §4.4.1: IND, PNU, instance
// HART 7 command 48 (manual §5.1.22 names the request's status bytes): a warning, not an error.
constexpr std::uint8_t kStatusBytesMismatch = 14;

Reply mismatch()
{
    Reply reply;
    reply.status = ReplyStatus::Mismatch;
    return reply;
}

bool fitsByte(int v)
{
    return v >= 0 && v <= 0xFF;
}

// §4.4.1: "IND and PNU correspond to the description of the parameter; the instance number
// corresponds to the channel number".
std::optional<hart::ParamRef> paramRefOf(const ParamMeta &row)
{
    if (!row.ind || !row.pnu || !fitsByte(*row.ind) || !fitsByte(*row.pnu) ||
        !fitsByte(row.instance))
        return std::nullopt;
    return hart::ParamRef{static_cast<std::uint8_t>(*row.ind), static_cast<std::uint8_t>(*row.pnu),
                          static_cast<std::uint8_t>(row.instance)};
}

// The first status byte of a response (§4.4.1 "Status"): bit 7 set = communication error bits.
LocalText statusText(std::uint8_t code)
{
    if ((code & 0x80) == 0)
        return hart::responseCodeText(code);
    LocalText text{"communication error:", "Kommunikationsfehler:"};
    for (int bit = 6; bit >= 0; --bit) {
        if ((code >> bit) & 1) {
            const LocalText b = hart::commErrorBitText(bit);
            text.en += " " + b.en;
            text.de += " " + b.de;
        }
    }
    return text;
}

Reply exceptionReply(std::uint8_t code)
{
    Reply reply;
    reply.status = ReplyStatus::DeviceException;
    reply.exceptionCode = code;
    reply.exceptionText = statusText(code);
    return reply;
}

std::string hexText(std::uint32_t value, int digits)
{
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out = "0x";
    for (int i = digits - 1; i >= 0; --i)
        out += kDigits[(value >> (4 * i)) & 0xF];
    return out;
}

} // namespace

std::optional<hart::ValueType> hartValueType(const ParamMeta &row)
{
    switch (row.type) {
    case RawType::Int8: return hart::ValueType::Int8;
    case RawType::UInt8: return hart::ValueType::UInt8;
    case RawType::Int16: return hart::ValueType::Int16;
    case RawType::UInt16: return hart::ValueType::UInt16;
    case RawType::Int32: return hart::ValueType::Int32;
    case RawType::UInt32: return hart::ValueType::UInt32;
    case RawType::Float32: return hart::ValueType::Float;
    case RawType::String: break;
    }
    return std::nullopt;
}

std::vector<Transaction> HartAdapter::planRead(int module,
                                               std::span<const ParamMeta *const> rows) const
{
    std::vector<Transaction> plan;
    std::map<std::uint8_t, std::size_t> universal; // read command -> its transaction in plan
    for (const ParamMeta *row : rows) {
        if (!row || !row->readable())
            continue;
        if (const auto field = universalField(*row)) {
            // One exchange answers every field of the same universal command.
            const auto [it, added] = universal.emplace(field->readCommand, plan.size());
            if (added)
                plan.push_back(Transaction::read(module, {row}));
            else
                plan[it->second].rows.push_back(row);
        } else if (paramRefOf(*row) && hartValueType(*row)) {
            plan.push_back(Transaction::read(module, {row}));
        }
    }
    return plan;
}

std::vector<Transaction> HartAdapter::planIdentify(int module) const
{
    return {Transaction::identify(module)};
}

std::optional<hart::Address> HartAdapter::longAddressOf(int module) const
{
    const auto it = m_devices.find(module);
    if (it == m_devices.end())
        return std::nullopt;
    return it->second.address;
}

void HartAdapter::setLongAddress(int module, hart::Address address, std::size_t requestPreambles)
{
    address.isLong = true;
    address.primaryMaster = m_options.primaryMaster;
    address.burst = false;
    m_devices[module] = Device{address, requestPreambles, {}, {}};
}

Bytes HartAdapter::encode(const Transaction &t)
{
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    hart::Frame frame;
    std::size_t preambles = m_options.requestPreambles;
    if (t.kind == TransactionKind::Identify) {
        // §2.3 / ARCHITECTURE.md: command 0 is the one command a short frame may carry.
        if (t.module < 0 || t.module > hart::kMaxPollAddress)
            return {};
        frame = hart::makeRequest(
            hart::shortAddress(static_cast<std::uint8_t>(t.module), m_options.primaryMaster),
            kReadUniqueIdentifier);
    } else {
        const auto device = m_devices.find(t.module);
        if (device == m_devices.end() || t.rows.empty() || !t.rows.front())
            return {}; // not identified yet: no address to send to
        if (universalField(*t.rows.front()))
            return encodeUniversal(t, device->second);
        if (t.rows.size() != 1)
            return {};
        const ParamMeta &row = *t.rows.front();
        const auto ref = paramRefOf(row);
        const auto type = hartValueType(row);
        if (!ref || !type)
            return {};
        hart::ParamAccess access = hart::readParam(*type, *ref);
        if (t.kind == TransactionKind::Write) {
            // §2.3: big-endian, IEEE 754 for float rows; the command's width (§4.4.1 table).
            const auto bits =
                t.values.size() == 1 ? rawToWireBits(row, t.values.front()) : std::nullopt;
            if (!bits)
                return {};
            access = hart::writeParam(*type, *ref, *bits);
        }
        auto data = hart::encodeParamAccess(access, false);
        if (!data)
            return {};
        frame = hart::makeRequest(device->second.address, access.command, std::move(*data));
        preambles = std::max(preambles, device->second.requestPreambles);
    }
    frame.preambles = std::clamp<std::size_t>(preambles, 2, hart::kMaxPreambles);
    auto bytes = hart::encodeFrame(frame);
    return bytes ? std::move(*bytes) : Bytes{};
}

std::size_t HartAdapter::expectedReplyBytes(const Transaction &t) const
{
    // §2.3: preambles | SD | AD | CD | BC | status (2) | data | parity.
    constexpr std::size_t kFixed = 1 + 1 + 1 + 2 + 1;
    switch (t.kind) {
    case TransactionKind::Identify:
        return m_options.maxResponsePreambles + kFixed + 1 + kCommand0Bytes;
    case TransactionKind::Read:
    case TransactionKind::Write: {
        if (!t.rows.empty() && t.rows.front() && universalField(*t.rows.front()))
            return m_options.maxResponsePreambles + hart::kMaxFrameSize;
        const auto type =
            t.rows.size() == 1 && t.rows.front() ? hartValueType(*t.rows.front()) : std::nullopt;
        const std::size_t width = type ? hart::valueWidth(*type) : 4;
        return m_options.maxResponsePreambles + kFixed + 5 + kParamRefBytes + width;
    }
    case TransactionKind::Raw: break;
    }
    return m_options.maxResponsePreambles + hart::kMaxFrameSize;
}

std::optional<Reply> HartAdapter::feed(std::span<const std::uint8_t> bytes, const Transaction &t)
{
    std::optional<Reply> result;
    for (hart::DeframerEvent &event : m_deframer.feed(bytes)) {
        if (event.kind != hart::DeframerEvent::Kind::Frame)
            continue; // bad checksum, bad delimiter: the de-framer resynchronises on preambles
        if (result && result->status != ReplyStatus::Mismatch)
            continue;
        std::optional<Reply> reply = frameReply(event.frame, t);
        if (!reply)
            continue;
        reply->frame = std::move(event.raw);
        offerReply(result, std::move(*reply)); // later frames are still drained, not answered
    }
    return result;
}

void HartAdapter::resetFraming()
{
    m_deframer.reset();
}

std::optional<Reply> HartAdapter::frameReply(const hart::Frame &frame, const Transaction &t)
{
    if (!frame.isResponse())
        return std::nullopt; // our own request echoed by a two-wire modem, another master's
    if (t.kind == TransactionKind::Raw)
        return Reply{};
    // §2.3: a burst frame (BACK) answers nobody; the master bit says which master is answered.
    if (frame.type != hart::FrameType::Ack ||
        frame.address.primaryMaster != m_options.primaryMaster)
        return mismatch();
    if (t.kind == TransactionKind::Identify) {
        if (frame.address.isLong || frame.address.pollAddress != t.module ||
            frame.command != kReadUniqueIdentifier)
            return mismatch();
        return identityReply(frame, t);
    }
    const auto device = m_devices.find(t.module);
    if (device == m_devices.end() || !frame.address.isLong ||
        frame.address.expandedDeviceType != device->second.address.expandedDeviceType ||
        frame.address.deviceId != device->second.address.deviceId)
        return mismatch();
    if (!t.rows.empty() && t.rows.front() && universalField(*t.rows.front()))
        return universalReply(frame, t);
    return parameterReply(frame, t);
}

Bytes HartAdapter::encodeUniversal(const Transaction &t, const Device &device)
{
    const auto field = universalField(*t.rows.front());
    Bytes data;
    std::uint8_t command = field->readCommand;
    if (t.kind == TransactionKind::Write) {
        if (t.rows.size() != 1 || t.values.size() != 1 || !field->writeCommand)
            return {};
        command = *field->writeCommand;
        data.assign(universalRecordSize(command), 0);
        if (command == 18) {
            // Tag, descriptor and date travel together: without the device's present record
            // the other two would be overwritten with blanks.
            if (device.tagDescriptorDate.size() != data.size())
                return {};
            data = device.tagDescriptorDate;
        }
        if (!encodeUniversalField(*field, t.values.front(), data))
            return {};
    } else {
        for (const ParamMeta *row : t.rows) {
            const auto other = row ? universalField(*row) : std::nullopt;
            if (!other || other->readCommand != command)
                return {};
        }
        if (command == 48)
            data = device.additionalStatus;
    }
    hart::Frame frame = hart::makeRequest(device.address, command, std::move(data));
    frame.preambles = std::clamp<std::size_t>(
        std::max(m_options.requestPreambles, device.requestPreambles), 2, hart::kMaxPreambles);
    auto bytes = hart::encodeFrame(frame);
    return bytes ? std::move(*bytes) : Bytes{};
}

Reply HartAdapter::universalReply(const hart::Frame &frame, const Transaction &t)
{
    const auto field = universalField(*t.rows.front());
    const std::uint8_t command = t.kind == TransactionKind::Write && field->writeCommand
                                     ? *field->writeCommand
                                     : field->readCommand;
    if (frame.command != command)
        return mismatch();
    if (hart::isErrorResponse(frame.responseCode))
        return exceptionReply(frame.responseCode);
    Reply reply;
    for (const ParamMeta *row : t.rows) {
        const auto f = universalField(*row);
        // A write's answer echoes the whole record, so the field sits where the read finds it.
        auto value = f ? decodeUniversalField(*f, frame.data, frame.deviceStatus) : std::nullopt;
        if (!value)
            return frame.responseCode == 0 ? mismatch() : exceptionReply(frame.responseCode);
        reply.values.push_back(std::move(*value));
    }
    // A warning (HART common codes such as 14 "status bytes mismatch"): the data arrived and is
    // the device's present value; the code and its text travel with it.
    if (frame.responseCode != 0) {
        reply.exceptionCode = frame.responseCode;
        reply.exceptionText =
            command == 48 && frame.responseCode == kStatusBytesMismatch
                ? LocalText{"status bytes mismatch: the device status changed since the last "
                            "read",
                            "Statusbytes abweichend: der Gerätestatus hat sich seit dem letzten "
                            "Lesen geändert"}
                : statusText(frame.responseCode);
    }
    Device &device = m_devices[t.module];
    if (command == 13 || command == 18)
        device.tagDescriptorDate.assign(
            frame.data.begin(),
            frame.data.begin() +
                std::ptrdiff_t(std::min<std::size_t>(frame.data.size(), universalRecordSize(18))));
    if (command == 48)
        device.additionalStatus = Bytes(frame.data.begin(), frame.data.end());
    return reply;
}

Reply HartAdapter::identityReply(const hart::Frame &frame, const Transaction &t)
{
    if (hart::isErrorResponse(frame.responseCode))
        return exceptionReply(frame.responseCode);
    Reply reply;
    const auto payload = hart::decodeUniversal(kReadUniqueIdentifier, true, frame.data);
    const auto *id = payload ? std::get_if<hart::Identity>(&*payload) : nullptr;
    if (!id)
        return mismatch(); // too short for command 0 (§5.1.1 needs 12 bytes at least)
    if (frame.responseCode != 0) {
        reply.exceptionCode = frame.responseCode;
        reply.exceptionText = statusText(frame.responseCode);
    }
    reply.identity.manufacturer = id->manufacturerId;
    reply.identity.expandedDeviceType = id->expandedDeviceType;
    reply.identity.deviceId = id->deviceId;
    // HART-7 manual §5.1.1 command 0: revision, manufacturer, device type and unique id.
    reply.identity.text = {
        "HART rev " + std::to_string(id->hartRevision) + ", manufacturer " +
            std::to_string(id->manufacturerId) + ", device type " +
            std::to_string(id->expandedDeviceType) + ", device id " + hexText(id->deviceId, 6),
        "HART-Revision " + std::to_string(id->hartRevision) + ", Hersteller " +
            std::to_string(id->manufacturerId) + ", Gerätetyp " +
            std::to_string(id->expandedDeviceType) + ", Geräte-ID " + hexText(id->deviceId, 6)};
    // From now on the device is addressed by its unique id (§2.3 long frame).
    m_devices[t.module] =
        Device{id->address(m_options.primaryMaster), id->minRequestPreambles, {}, {}};
    return reply;
}

Reply HartAdapter::parameterReply(const hart::Frame &frame, const Transaction &t) const
{
    if (t.rows.size() != 1 || !t.rows.front())
        return mismatch();
    const ParamMeta &row = *t.rows.front();
    const auto ref = paramRefOf(row);
    const auto type = hartValueType(row);
    if (!ref || !type)
        return mismatch();
    const std::uint8_t command =
        t.kind == TransactionKind::Write ? hart::writeCommand(*type) : hart::readCommand(*type);
    if (frame.command != command)
        return mismatch();
    // §4.4.1: status byte 1 = 0 no error, 5 wrong byte count, 6 device-specific error; error
    // responses carry no data.
    if (hart::isErrorResponse(frame.responseCode))
        return exceptionReply(frame.responseCode);
    Reply reply;
    const auto access = hart::decodeParamAccess(command, true, frame.data);
    if (!access || access->ref != *ref || !access->raw) {
        if (frame.responseCode == 0)
            return mismatch();
        // A warning without usable data: report the warning rather than wait for nothing.
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionCode = frame.responseCode;
        reply.exceptionText = statusText(frame.responseCode);
        return reply;
    }
    if (frame.responseCode != 0) {
        reply.exceptionCode = frame.responseCode;
        reply.exceptionText = statusText(frame.responseCode);
    }
    // A write answers with the value the device now holds (HART-7 manual §4.4.1, example 1).
    reply.values.emplace_back(wireBitsToRaw(row, *access->raw));
    return reply;
}

} // namespace vt::dev::access
