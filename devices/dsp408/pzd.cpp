#include "dsp408/pzd.h"

#include "core/byte_reader.h"
#include "core/hex.h"

#include <algorithm>
#include <string>

namespace vt::dev::dsp408 {
namespace {

// One PZD block: a 16-bit word and a 32-bit value in two words (§4.5.1).
struct RawPzd
{
    std::uint16_t word = 0;
    std::int32_t value = 0;
};

Bytes encodeRaw(const RawPzd &pzd, const Options &options)
{
    const auto v = static_cast<std::uint32_t>(pzd.value);
    const auto high = static_cast<std::uint16_t>(v >> 16);
    const auto low = static_cast<std::uint16_t>(v);
    ByteWriter w;
    w.u16be(pzd.word);
    if (options.pzdWordOrder == WordOrder::HighWordFirst)
        w.u16be(high).u16be(low);
    else
        w.u16be(low).u16be(high);
    return w.take();
}

Result<RawPzd, DecodeError> decodeRaw(std::span<const std::uint8_t> bytes, const Options &options)
{
    ByteReader r(bytes);
    const std::uint16_t word = r.u16be();
    const std::uint16_t first = r.u16be();
    const std::uint16_t second = r.u16be();
    if (r.failed())
        return DecodeError{DecodeErrc::Truncated, r.failOffset(), 0,
                           "PZD needs 6 bytes, got " + std::to_string(bytes.size())};
    if (!r.atEnd())
        return DecodeError{DecodeErrc::TooLong, kPzdSize, 0,
                           std::to_string(bytes.size() - kPzdSize) + " bytes after the PZD"};
    const bool highFirst = options.pzdWordOrder == WordOrder::HighWordFirst;
    const std::uint32_t high = highFirst ? first : second;
    const std::uint32_t low = highFirst ? second : first;
    return RawPzd{word, static_cast<std::int32_t>(high << 16 | low)};
}

// Telegram type to use for `size` bytes, or an error naming the sizes that fit.
Result<TelegramType, DecodeError> typeFor(std::size_t size, const Options &options)
{
    if (options.telegramType)
        return *options.telegramType;
    if (size == kTelegram1Size)
        return TelegramType::PkwAndPzd;
    if (size == kPzdSize)
        return TelegramType::PzdOnly;
    return DecodeError{DecodeErrc::BadLength, 0, 0,
                       std::to_string(size) + " bytes: telegram type 1 has 14, type 2 has 6"};
}

std::string wordValue(std::uint16_t w)
{
    return hexWord(w);
}

void describeWordBits(std::uint16_t word, std::size_t offset, bool control,
                      std::vector<FieldSpan> &out)
{
    for (int bit = 0; bit < 16; ++bit) {
        const LocalText text = control ? controlBitText(bit) : statusBitText(bit);
        const bool set = ((static_cast<unsigned>(word) >> static_cast<unsigned>(bit)) & 1u) != 0;
        // Only the bits the manual names, plus any reserved bit that is set.
        if (!set && text.en == "reserved")
            continue;
        const std::size_t byte = bit < 8 ? offset + 1 : offset; // big-endian word
        out.push_back(
            {std::string(control ? "pzd.control.bit" : "pzd.status.bit") + std::to_string(bit),
             byte, 1, 1, set ? "1" : "0", text});
    }
}

void describePzdFields(const RawPzd &pzd, std::size_t offset, const Options &options,
                       std::vector<FieldSpan> &out)
{
    const bool request = options.direction == Direction::Request;
    if (request)
        out.push_back({"pzd.control_word",
                       offset,
                       2,
                       0,
                       wordValue(pzd.word),
                       {"control word (db_ControlWord)", "Steuerwort (db_ControlWord)"}});
    else
        out.push_back({"pzd.status_word",
                       offset,
                       2,
                       0,
                       wordValue(pzd.word),
                       {"status word (db_StatusWord)", "Zustandswort (db_StatusWord)"}});
    describeWordBits(pzd.word, offset, request, out);
    const LocalText order = options.pzdWordOrder == WordOrder::HighWordFirst
                                ? LocalText{"high word first", "High-Wort zuerst"}
                                : LocalText{"low word first", "Low-Wort zuerst"};
    if (request)
        out.push_back({"pzd.setpoint",
                       offset + 2,
                       4,
                       0,
                       std::to_string(pzd.value),
                       {"set value (dpc_SetpointVal), " + order.en,
                        "Sollwert (dpc_SetpointVal), " + order.de}});
    else
        out.push_back({"pzd.actual_value",
                       offset + 2,
                       4,
                       0,
                       std::to_string(pzd.value),
                       {"actual value (dpc_ActualVal), " + order.en,
                        "Istwert (dpc_ActualVal), " + order.de}});
}

LocalText pzdSummary(const RawPzd &pzd, Direction direction)
{
    const std::string w = wordValue(pzd.word);
    const std::string v = std::to_string(pzd.value);
    if (direction == Direction::Request)
        return {"control word " + w + ", set value " + v, "Steuerwort " + w + ", Sollwert " + v};
    return {"status word " + w + ", actual value " + v, "Zustandswort " + w + ", Istwert " + v};
}

template<typename Telegram, typename Pzd>
Result<Telegram, DecodeError> decodeTelegramAs(std::span<const std::uint8_t> bytes,
                                               const Options &options, Direction direction,
                                               Pzd (*make)(const RawPzd &))
{
    auto type = typeFor(bytes.size(), options);
    if (!type.ok())
        return type.error();
    Options o = options;
    o.direction = direction;
    Telegram t;
    std::size_t pzdAt = 0;
    if (*type == TelegramType::PkwAndPzd) {
        if (bytes.size() < kPkwSize)
            return DecodeError{DecodeErrc::Truncated, bytes.size(), 0,
                               "telegram type 1 needs 14 bytes"};
        auto pkw = decodePkw(bytes.first(kPkwSize), o);
        if (!pkw.ok())
            return pkw.error();
        t.pkw = *pkw;
        pzdAt = kPkwSize;
    }
    auto raw = decodeRaw(bytes.subspan(pzdAt), o);
    if (!raw.ok()) {
        DecodeError e = raw.error();
        e.offset += pzdAt;
        return e;
    }
    t.pzd = make(*raw);
    return t;
}

PzdSetpoint toSetpoint(const RawPzd &raw)
{
    return {raw.word, raw.value};
}

PzdActual toActual(const RawPzd &raw)
{
    return {raw.word, raw.value};
}

template<typename Telegram>
Result<Bytes, DecodeError> encodeTelegramAs(const Telegram &t, const RawPzd &raw,
                                            const Options &options)
{
    Bytes out;
    if (t.pkw) {
        auto pkw = encodePkw(*t.pkw, options);
        if (!pkw.ok())
            return pkw.error();
        out = *pkw;
    }
    const Bytes pzd = encodeRaw(raw, options);
    out.insert(out.end(), pzd.begin(), pzd.end());
    return out;
}

} // namespace

Bytes encodePzd(const PzdSetpoint &pzd, const Options &options)
{
    return encodeRaw({pzd.controlWord, pzd.setpoint}, options);
}

Bytes encodePzd(const PzdActual &pzd, const Options &options)
{
    return encodeRaw({pzd.statusWord, pzd.actualValue}, options);
}

Result<PzdSetpoint, DecodeError> decodePzdSetpoint(std::span<const std::uint8_t> bytes,
                                                   const Options &options)
{
    auto raw = decodeRaw(bytes, options);
    if (!raw.ok())
        return raw.error();
    return toSetpoint(*raw);
}

Result<PzdActual, DecodeError> decodePzdActual(std::span<const std::uint8_t> bytes,
                                               const Options &options)
{
    auto raw = decodeRaw(bytes, options);
    if (!raw.ok())
        return raw.error();
    return toActual(*raw);
}

Result<Bytes, DecodeError> encodeTelegram(const RequestTelegram &telegram, const Options &options)
{
    return encodeTelegramAs(telegram, {telegram.pzd.controlWord, telegram.pzd.setpoint}, options);
}

Result<Bytes, DecodeError> encodeTelegram(const ResponseTelegram &telegram, const Options &options)
{
    return encodeTelegramAs(telegram, {telegram.pzd.statusWord, telegram.pzd.actualValue}, options);
}

Result<RequestTelegram, DecodeError> decodeRequestTelegram(std::span<const std::uint8_t> bytes,
                                                           const Options &options)
{
    return decodeTelegramAs<RequestTelegram>(bytes, options, Direction::Request, &toSetpoint);
}

Result<ResponseTelegram, DecodeError> decodeResponseTelegram(std::span<const std::uint8_t> bytes,
                                                             const Options &options)
{
    return decodeTelegramAs<ResponseTelegram>(bytes, options, Direction::Response, &toActual);
}

Description describeTelegram(std::span<const std::uint8_t> bytes, const Options &options)
{
    Description d;
    d.protocol = "dsp408-pzd";
    auto type = typeFor(bytes.size(), options);
    if (!type.ok()) {
        d.error = type.error();
        d.summary = describeError(type.error());
        return d;
    }
    const bool withPkw = *type == TelegramType::PkwAndPzd;
    d.fields.push_back({"telegram.type", 0, 0, 0, withPkw ? "1" : "2",
                        withPkw
                            ? LocalText{"telegram type 1 (PKW + PZD)", "Telegrammtyp 1 (PKW + PZD)"}
                            : LocalText{"telegram type 2 (PZD only)", "Telegrammtyp 2 (nur PZD)"}});
    LocalText summary;
    std::size_t pzdAt = 0;
    if (withPkw) {
        const Description pkw = describePkw(bytes.first(std::min(bytes.size(), kPkwSize)), options);
        d.fields.insert(d.fields.end(), pkw.fields.begin(), pkw.fields.end());
        if (pkw.error) {
            d.error = pkw.error;
            d.summary = pkw.summary;
            return d;
        }
        summary = pkw.summary;
        summary.en += "; ";
        summary.de += "; ";
        pzdAt = kPkwSize;
    }
    auto raw = decodeRaw(bytes.subspan(pzdAt), options);
    if (!raw.ok()) {
        DecodeError e = raw.error();
        e.offset += pzdAt;
        d.error = e;
        d.summary = describeError(e);
        return d;
    }
    describePzdFields(*raw, pzdAt, options, d.fields);
    const LocalText pzd = pzdSummary(*raw, options.direction);
    d.summary = {summary.en + pzd.en, summary.de + pzd.de};
    return d;
}

} // namespace vt::dev::dsp408
