#include "hart/universal.h"

#include "core/byte_reader.h"

#include <algorithm>
#include <string>

namespace vt::dev::hart {
namespace {

// Sizes of the fixed layouts (HART-7 manual §5.1).
constexpr std::size_t kIdentityMin = 12; // HART 5 part of command 0
constexpr std::size_t kTagSize = 6;
constexpr std::size_t kDescriptorSize = 12;
constexpr std::size_t kMessageSize = 24;
constexpr std::size_t kLongTagSize = 32;
constexpr std::size_t kTddSize = kTagSize + kDescriptorSize + 3;
constexpr std::size_t kMaxStatusBytes = 25;
constexpr std::size_t kMaxSlots = 8;

std::uint32_t u24(ByteReader &r)
{
    const std::uint32_t high = r.u8();
    return high << 16 | r.u16be();
}

float f32(ByteReader &r)
{
    return floatFromBits(r.u32be());
}

Identity readIdentity(ByteReader &r, std::size_t size)
{
    Identity id;
    id.expansionCode = r.u8();
    id.expandedDeviceType = r.u16be();
    id.minRequestPreambles = r.u8();
    id.hartRevision = r.u8();
    id.deviceRevision = r.u8();
    id.softwareRevision = r.u8();
    id.hardwareRevisionAndSignaling = r.u8();
    id.flags = r.u8();
    id.deviceId = u24(r);
    // HART 6/7 additions: on a short reply the reader latches failure and every later read is 0,
    // so absent fields stay 0 (never half-filled).
    id.minResponsePreambles = r.u8();
    id.maxDeviceVariables = r.u8();
    id.configChangeCounter = r.u16be();
    id.extendedStatus = r.u8();
    id.manufacturerId = r.u16be();
    id.privateLabel = r.u16be();
    id.deviceProfile = r.u8();
    id.length = std::min<std::size_t>(size, 22);
    return id;
}

UnitValue readUnitValue(ByteReader &r)
{
    UnitValue v;
    v.unit = r.u8();
    v.value = f32(r);
    return v;
}

TagDescriptorDate readTdd(ByteReader &r)
{
    TagDescriptorDate t;
    t.tag = unpackAscii(r.bytes(kTagSize));
    t.descriptor = unpackAscii(r.bytes(kDescriptorSize));
    t.date.day = r.u8();
    t.date.month = r.u8();
    t.date.yearSince1900 = r.u8();
    return t;
}

DecodeError tooShort(std::uint8_t command, std::size_t need, std::size_t got)
{
    return DecodeError{DecodeErrc::BadLength, got, 0,
                       "command " + std::to_string(command) + " needs " + std::to_string(need) +
                           " data bytes, got " + std::to_string(got)};
}

// Minimum data size of each universal command and direction; nullopt = not universal.
std::optional<std::size_t> minimumSize(std::uint8_t command, bool response)
{
    switch (command) {
    case 0: return response ? kIdentityMin : 0;
    case 1: return response ? 5 : 0;
    case 2: return response ? 8 : 0;
    case 3: return response ? 9 : 0;
    case 6: return 1;
    case 7: return response ? 2 : 0;
    case 8: return response ? 4 : 0;
    case 9: return response ? 9 : 1;
    case 11: return response ? kIdentityMin : kTagSize;
    case 12: return response ? kMessageSize : 0;
    case 13: return response ? kTddSize : 0;
    case 14: return response ? 16 : 0;
    case 15: return response ? 18 : 0;
    case 16: return response ? 3 : 0;
    case 17: return kMessageSize;
    case 18: return kTddSize;
    case 19: return 3;
    case 20: return response ? kLongTagSize : 0;
    case 21: return response ? kIdentityMin : kLongTagSize;
    case 22: return kLongTagSize;
    case 38: return 0;
    case 48: return 0;
    default: return std::nullopt;
    }
}

Payload decodeKnown(std::uint8_t command, bool response, ByteReader &r, std::size_t size)
{
    switch (command) {
    case 0: return readIdentity(r, size);
    case 11:
    case 21:
        if (response)
            return readIdentity(r, size);
        if (command == 11)
            return Tag{unpackAscii(r.bytes(kTagSize))};
        return LongTag{latin1ToUtf8(r.bytes(kLongTagSize))};
    case 1: return readUnitValue(r);
    case 2: {
        LoopCurrent c;
        c.currentMa = f32(r);
        c.percentOfRange = f32(r);
        return c;
    }
    case 3: {
        DynamicVariables d;
        d.loopCurrentMa = f32(r);
        while (d.variables.size() < 4 && r.remaining() >= 5)
            d.variables.push_back(readUnitValue(r));
        return d;
    }
    case 6:
    case 7: {
        LoopConfiguration c;
        c.pollAddress = r.u8();
        if (r.remaining() >= 1)
            c.loopCurrentMode = r.u8();
        return c;
    }
    case 8: {
        VariableClassifications v;
        for (auto &code : v.codes)
            code = r.u8();
        return v;
    }
    case 9: {
        if (!response) {
            DeviceVariableCodes c;
            while (c.codes.size() < kMaxSlots && r.remaining() >= 1)
                c.codes.push_back(r.u8());
            return c;
        }
        DeviceVariables d;
        d.extendedStatus = r.u8();
        while (d.variableSlots.size() < kMaxSlots && r.remaining() >= 8) {
            DeviceVariableSlot s;
            s.code = r.u8();
            s.classification = r.u8();
            s.unit = r.u8();
            s.value = f32(r);
            s.status = r.u8();
            d.variableSlots.push_back(s);
        }
        if (r.remaining() >= 4)
            d.timestamp = r.u32be();
        return d;
    }
    case 12:
    case 17: return Message{unpackAscii(r.bytes(kMessageSize))};
    case 13:
    case 18: return readTdd(r);
    case 14: {
        TransducerInfo t;
        t.serialNumber = u24(r);
        t.unit = r.u8();
        t.upperLimit = f32(r);
        t.lowerLimit = f32(r);
        t.minimumSpan = f32(r);
        return t;
    }
    case 15: {
        DeviceInfo i;
        i.alarmSelection = r.u8();
        i.transferFunction = r.u8();
        i.rangeUnit = r.u8();
        i.upperRange = f32(r);
        i.lowerRange = f32(r);
        i.damping = f32(r);
        i.writeProtect = r.u8();
        i.reserved = r.u8();
        i.analogChannelFlags = r.u8();
        return i;
    }
    case 16:
    case 19: return FinalAssemblyNumber{u24(r)};
    case 20:
    case 22: return LongTag{latin1ToUtf8(r.bytes(kLongTagSize))};
    case 38: {
        ConfigChangeCounter c;
        if (r.remaining() >= 2)
            c.counter = r.u16be();
        return c;
    }
    case 48: {
        const auto b = r.bytes(std::min(r.remaining(), kMaxStatusBytes));
        return AdditionalStatus{Bytes(b.begin(), b.end())};
    }
    default: return std::monostate{};
    }
}

struct Encoder
{
    ByteWriter &w;

    void f32(float v) { w.u32be(bitsFromFloat(v)); }
    void u24(std::uint32_t v)
    {
        w.u8(static_cast<std::uint8_t>(v >> 16)).u16be(static_cast<std::uint16_t>(v));
    }
    void unitValue(const UnitValue &v)
    {
        w.u8(v.unit);
        f32(v.value);
    }

    void operator()(const std::monostate &) {}
    void operator()(const Identity &id)
    {
        w.u8(id.expansionCode)
            .u16be(id.expandedDeviceType)
            .u8(id.minRequestPreambles)
            .u8(id.hartRevision);
        w.u8(id.deviceRevision)
            .u8(id.softwareRevision)
            .u8(id.hardwareRevisionAndSignaling)
            .u8(id.flags);
        u24(id.deviceId);
        w.u8(id.minResponsePreambles).u8(id.maxDeviceVariables).u16be(id.configChangeCounter);
        w.u8(id.extendedStatus)
            .u16be(id.manufacturerId)
            .u16be(id.privateLabel)
            .u8(id.deviceProfile);
    }
    void operator()(const UnitValue &v) { unitValue(v); }
    void operator()(const LoopCurrent &c)
    {
        f32(c.currentMa);
        f32(c.percentOfRange);
    }
    void operator()(const DynamicVariables &d)
    {
        f32(d.loopCurrentMa);
        for (std::size_t i = 0; i < d.variables.size() && i < 4; ++i)
            unitValue(d.variables[i]);
    }
    void operator()(const LoopConfiguration &c) { w.u8(c.pollAddress).u8(c.loopCurrentMode); }
    void operator()(const VariableClassifications &v) { w.bytes(v.codes); }
    void operator()(const DeviceVariableCodes &c)
    {
        w.bytes(std::span<const std::uint8_t>(c.codes).first(std::min(c.codes.size(), kMaxSlots)));
    }
    void operator()(const DeviceVariables &d)
    {
        w.u8(d.extendedStatus);
        for (std::size_t i = 0; i < d.variableSlots.size() && i < kMaxSlots; ++i) {
            const DeviceVariableSlot &s = d.variableSlots[i];
            w.u8(s.code).u8(s.classification).u8(s.unit);
            f32(s.value);
            w.u8(s.status);
        }
        if (d.timestamp)
            w.u32be(*d.timestamp);
    }
    void operator()(const Tag &t) { w.bytes(packAscii(t.tag, kTagSize)); }
    void operator()(const Message &m) { w.bytes(packAscii(m.text, kMessageSize)); }
    void operator()(const TagDescriptorDate &t)
    {
        w.bytes(packAscii(t.tag, kTagSize)).bytes(packAscii(t.descriptor, kDescriptorSize));
        w.u8(t.date.day).u8(t.date.month).u8(t.date.yearSince1900);
    }
    void operator()(const TransducerInfo &t)
    {
        u24(t.serialNumber);
        w.u8(t.unit);
        f32(t.upperLimit);
        f32(t.lowerLimit);
        f32(t.minimumSpan);
    }
    void operator()(const DeviceInfo &i)
    {
        w.u8(i.alarmSelection).u8(i.transferFunction).u8(i.rangeUnit);
        f32(i.upperRange);
        f32(i.lowerRange);
        f32(i.damping);
        w.u8(i.writeProtect).u8(i.reserved).u8(i.analogChannelFlags);
    }
    void operator()(const FinalAssemblyNumber &f) { u24(f.number); }
    void operator()(const LongTag &t) { w.bytes(utf8ToLatin1(t.text, kLongTagSize)); }
    void operator()(const ConfigChangeCounter &c)
    {
        if (c.counter)
            w.u16be(*c.counter);
    }
    void operator()(const AdditionalStatus &s)
    {
        w.bytes(std::span<const std::uint8_t>(s.bytes).first(
            std::min(s.bytes.size(), kMaxStatusBytes)));
    }
};

} // namespace

bool isUniversal(std::uint8_t command)
{
    return minimumSize(command, false).has_value();
}

Result<Payload, DecodeError> decodeUniversal(std::uint8_t command, bool response,
                                             std::span<const std::uint8_t> data)
{
    const auto need = minimumSize(command, response);
    if (!need)
        return DecodeError{DecodeErrc::UnexpectedCommand, 0, command,
                           "command " + std::to_string(command) + " is not a universal command"};
    if (data.size() < *need)
        return tooShort(command, *need, data.size());
    if (*need == 0 && command != 38 && command != 48)
        return Payload{std::monostate{}};
    if (command == 38 && data.size() == 1)
        return tooShort(command, 2, 1);
    ByteReader r(data);
    return decodeKnown(command, response, r, data.size());
}

Bytes encodePayload(const Payload &payload)
{
    ByteWriter w;
    std::visit(Encoder{w}, payload);
    return w.take();
}

} // namespace vt::dev::hart
