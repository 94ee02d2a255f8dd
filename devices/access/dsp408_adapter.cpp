#include "dsp408_adapter.h"

#include "access/wire_value.h"
#include "modbus/exceptions.h"
#include "modbus/register_image.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <variant>

namespace vt::dev::access {

namespace {

using dsp408::Pkw;

constexpr std::size_t kImageBytes = dsp408::kTelegram1Size;
// An FC 3 / FC 4 answer carrying the 7 registers of the input image: MBAP + fc + count + data.
constexpr std::size_t kGatewayAnswerBytes = modbus::kMbapSize + 2 + kImageBytes;

Reply mismatch()
{
    Reply reply;
    reply.status = ReplyStatus::Mismatch;
    return reply;
}

Reply progress(Bytes next, bool afterCycle)
{
    Reply reply;
    reply.status = ReplyStatus::Progress;
    reply.next = std::move(next);
    reply.nextAfterCycle = afterCycle;
    return reply;
}

std::optional<dsp408::ParamLength> lengthOf(RawType type)
{
    switch (wireBytes(type)) {
    case 1: return dsp408::ParamLength::Byte;
    case 2: return dsp408::ParamLength::Word;
    case 4: return dsp408::ParamLength::DoubleWord;
    default: return std::nullopt;
    }
}

bool addressable(const ParamMeta &row)
{
    return row.ind && row.pnu && *row.ind >= 0 && *row.ind <= 0xFF && *row.pnu >= 0 &&
           *row.pnu <= dsp408::kMaxPnu && lengthOf(row.type);
}

dsp408::Options layoutFor(const dsp408::Options &options, Direction direction)
{
    dsp408::Options o = options;
    o.direction = direction;
    o.telegramType = dsp408::TelegramType::PkwAndPzd;
    return o;
}

} // namespace

Dsp408Adapter::Dsp408Adapter(LinkProtocol carrier, Dsp408LinkOptions options)
    : m_carrier(carrier), m_options(options)
{
}

std::vector<Transaction> Dsp408Adapter::planRead(int module,
                                                 std::span<const ParamMeta *const> rows) const
{
    std::vector<Transaction> plan;
    for (const ParamMeta *row : rows)
        if (row && row->readable() && addressable(*row))
            plan.push_back(Transaction::read(module, {row}));
    return plan;
}

std::vector<Transaction> Dsp408Adapter::planIdentify(int module) const
{
    return {Transaction::identify(module)};
}

bool Dsp408Adapter::isPzdWrite(const Transaction &t) const
{
    // §4.5.2: control word (PZD 001) and set value (PZD 012) travel in every output image; a
    // PKW write of them would be overwritten by the next image's PZD.
    return t.kind == TransactionKind::Write && t.rows.size() == 1 && t.rows.front() &&
           t.rows.front()->pzd && t.rows.front()->writable();
}

std::optional<Pkw> Dsp408Adapter::requestOf(const Transaction &t) const
{
    if (t.kind == TransactionKind::Identify)
        return dsp408::readRequest(kCapabilityInd, kCapabilityPnu);
    if (t.rows.size() != 1 || !t.rows.front() || !addressable(*t.rows.front()))
        return std::nullopt;
    const ParamMeta &row = *t.rows.front();
    const auto ind = static_cast<std::uint8_t>(*row.ind);
    const auto pnu = static_cast<std::uint16_t>(*row.pnu);
    if (t.kind == TransactionKind::Read)
        return dsp408::readRequest(ind, pnu);
    if (t.values.size() != 1)
        return std::nullopt;
    const auto bits = rawToWireBits(row, t.values.front());
    if (!bits)
        return std::nullopt;
    return dsp408::writeRequest(ind, pnu, *lengthOf(row.type), *bits);
}

bool Dsp408Adapter::mayStillShow(const Pkw &request) const
{
    return std::any_of(m_uncleared.begin(), m_uncleared.end(),
                       [&](const Pkw &p) { return p.ind == request.ind && p.pnu == request.pnu; });
}

Bytes Dsp408Adapter::writeRegisters(std::uint16_t offset, std::vector<std::uint16_t> values)
{
    const auto pdu = modbus::encodeRegisterPdu(modbus::RegisterRequest{modbus::RegisterWrite{
        static_cast<std::uint16_t>(m_options.gateway.outputRegister + offset), std::move(values)}});
    if (!pdu.ok())
        return {};
    m_wait = Wait::WriteAck;
    return modbus::wrapAdu(++m_transaction, m_unit, *pdu);
}

Bytes Dsp408Adapter::readInput()
{
    const auto pdu = modbus::encodeRegisterPdu(modbus::RegisterRequest{
        modbus::RegisterRead{static_cast<std::uint8_t>(m_options.gateway.inputFunction),
                             m_options.gateway.inputRegister, dsp408::kImageRegisters}});
    if (!pdu.ok())
        return {};
    m_wait = Wait::ReadAnswer;
    return modbus::wrapAdu(++m_transaction, m_unit, *pdu);
}

Bytes Dsp408Adapter::sendPkw(const Pkw &pkw)
{
    if (m_carrier == LinkProtocol::Dsp408Image) {
        m_wait = Wait::Image;
        auto image = dsp408::encodeTelegram(dsp408::RequestTelegram{pkw, m_pzdOut},
                                            layoutFor(m_options.layout, Direction::Request));
        return image.ok() ? *image : Bytes{};
    }
    // The gateway keeps the PZD registers as last written: only the PKW words change.
    auto bytes = dsp408::encodePkw(pkw, layoutFor(m_options.layout, Direction::Request));
    if (!bytes.ok())
        return {};
    return writeRegisters(0, dsp408::toRegisters(*bytes, m_options.gateway.byteOrder));
}

Bytes Dsp408Adapter::encode(const Transaction &t)
{
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    if (m_carrier == LinkProtocol::Dsp408Gateway && (t.module < 0 || t.module > 0xFF))
        return {};
    m_unit = static_cast<std::uint8_t>(t.module & 0xFF);
    if (isPzdWrite(t)) {
        const ParamMeta &row = *t.rows.front();
        const auto bits = t.values.size() == 1 ? rawToWireBits(row, t.values.front())
                                               : std::optional<std::uint32_t>{};
        if (!bits)
            return {};
        m_phase = Phase::PzdWrite;
        m_request = Pkw{};
        const bool control = wireBytes(row.type) == 2;
        if (control)
            m_pzdOut.controlWord = static_cast<std::uint16_t>(*bits);
        else
            m_pzdOut.setpoint = static_cast<std::int32_t>(*bits);
        if (m_carrier == LinkProtocol::Dsp408Image)
            return sendPkw(Pkw{}); // the image carries the new PZD and "no instruction"
        // Only the field's registers, laid out as in the image (§4.5.2: control word in PZD
        // word 1, the set value in words 2..3 in the configured word order).
        const Bytes pzd =
            dsp408::encodePzd(m_pzdOut, layoutFor(m_options.layout, Direction::Request));
        const auto registers = dsp408::toRegisters(pzd, m_options.gateway.byteOrder);
        if (control)
            return writeRegisters(dsp408::kControlWordRegister, {registers[0]});
        return writeRegisters(dsp408::kSetpointRegister, {registers[1], registers[2]});
    }
    const auto request = requestOf(t);
    if (!request)
        return {};
    m_request = *request;
    if (m_channelUnknown || mayStillShow(m_request)) {
        m_phase = Phase::Clear;
        return sendPkw(Pkw{});
    }
    m_phase = Phase::Request;
    m_uncleared.push_back(m_request);
    return sendPkw(m_request);
}

std::size_t Dsp408Adapter::expectedReplyBytes(const Transaction &) const
{
    return m_carrier == LinkProtocol::Dsp408Image ? kImageBytes : kGatewayAnswerBytes;
}

Reply Dsp408Adapter::answerOf(const Pkw &response, const Transaction &t) const
{
    Reply reply;
    if (const auto code = dsp408::errorCode(response)) {
        // ED1/SD1 manual §4.6: AK 7, error number in PWE bytes 6..7.
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionCode = *code;
        reply.exceptionText = dsp408::pkwErrorText(*code);
        return reply;
    }
    const auto length = dsp408::responseLength(response.ak);
    const std::uint32_t bits = length ? dsp408::pweValue(response.pwe, *length) : 0;
    if (t.kind == TransactionKind::Identify) {
        reply.values.emplace_back(static_cast<double>(bits));
        reply.identity.capability = bits;
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08X", bits);
        reply.identity.text = same(std::string("DSP-408 db_Capability ") + hex);
        return reply;
    }
    const ParamMeta &row = *t.rows.front();
    const std::size_t width = wireBytes(row.type);
    const std::size_t got = length ? static_cast<std::size_t>(*length) : 0;
    if (got != width) {
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionText = {"the answer has " + std::to_string(got) + " bytes, the parameter " +
                                   std::to_string(width),
                               "die Antwort hat " + std::to_string(got) + " Byte, der Parameter " +
                                   std::to_string(width)};
        return reply;
    }
    reply.values.emplace_back(wireBitsToRaw(row, bits));
    return reply;
}

std::optional<Reply> Dsp408Adapter::onImage(std::span<const std::uint8_t> image,
                                            const Transaction &t)
{
    const auto decoded =
        dsp408::decodeResponseTelegram(image, layoutFor(m_options.layout, Direction::Response));
    const bool image_ = m_carrier == LinkProtocol::Dsp408Image;
    if (!decoded.ok() || !decoded->pkw) // an AK no response may carry: ask again
        return progress(
            image_ ? sendPkw(m_phase == Phase::Request ? m_request : Pkw{}) : readInput(), true);
    m_pzdIn = decoded->pzd;
    const Pkw &pkw = *decoded->pkw;
    if (t.kind == TransactionKind::Raw)
        return Reply{};
    const bool cleared = pkw.ak == static_cast<std::uint8_t>(dsp408::ResponseId::None);
    switch (m_phase) {
    case Phase::PzdWrite: {
        // PZD has no answer of its own (§4.5): the image that follows carries it.
        Reply reply;
        reply.values.push_back(t.values.front());
        return reply;
    }
    case Phase::Clear:
        if (!cleared)
            return progress(image_ ? sendPkw(Pkw{}) : readInput(), true);
        // Only here does an AK 0 answer mean that every earlier request is gone: in the other
        // phases it may be the answer to an AK 0 sent before the request on the wire.
        m_uncleared.clear();
        m_channelUnknown = false;
        m_phase = Phase::Request;
        m_uncleared.push_back(m_request);
        return progress(sendPkw(m_request), false);
    case Phase::Request:
        if (!dsp408::answers(pkw, m_request))
            // Not yet answered, or the answer to an older request: the PLC repeats its request
            // every cycle until the answer is there (§4.6.1 "on each request … a response").
            return progress(image_ ? sendPkw(m_request) : readInput(), true);
        return answerOf(pkw, t);
    }
    return std::nullopt;
}

std::optional<Reply> Dsp408Adapter::onAdu(std::span<const std::uint8_t> adu, const Transaction &t)
{
    auto cut = modbus::cutAdu(adu);
    if (!cut.ok() || !*cut)
        return mismatch();
    const modbus::AduCut &frame = **cut;
    if (frame.header.transaction != m_transaction || frame.header.unit != m_unit)
        return mismatch(); // a late answer to an earlier request, or another unit
    const auto response = modbus::decodeRegisterResponse(frame.pdu);
    if (!response.ok())
        return mismatch();
    if (t.kind == TransactionKind::Raw)
        return Reply{};
    if (const auto *e = std::get_if<modbus::RegisterException>(&*response)) {
        // The gateway refused (a register outside its map, the slave not in data exchange).
        Reply reply;
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionCode = e->code;
        reply.exceptionText = modbus::exceptionName(e->code).value_or(
            LocalText{"Modbus exception " + std::to_string(e->code),
                      "Modbus-Ausnahme " + std::to_string(e->code)});
        return reply;
    }
    if (m_wait == Wait::WriteAck &&
        std::holds_alternative<modbus::RegisterWriteAnswer>(*response)) {
        if (m_phase == Phase::PzdWrite) {
            Reply reply;
            reply.values.push_back(t.values.front());
            return reply;
        }
        return progress(readInput(), false);
    }
    const auto *read = std::get_if<modbus::RegisterReadAnswer>(&*response);
    if (m_wait != Wait::ReadAnswer || !read || read->registers.size() != dsp408::kImageRegisters)
        return mismatch();
    const Bytes image = dsp408::fromRegisters(read->registers, m_options.gateway.byteOrder);
    return onImage(image, t);
}

std::optional<Reply> Dsp408Adapter::feed(std::span<const std::uint8_t> bytes, const Transaction &t)
{
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::optional<Reply> result;
    std::size_t used = 0;
    while (used < m_buffer.size()) {
        const auto rest = std::span<const std::uint8_t>(m_buffer).subspan(used);
        std::span<const std::uint8_t> frame;
        std::optional<Reply> reply;
        if (m_carrier == LinkProtocol::Dsp408Image) {
            if (rest.size() < kImageBytes)
                break;
            frame = rest.first(kImageBytes);
            reply = onImage(frame, t);
        } else {
            auto cut = modbus::cutAdu(rest);
            if (!cut.ok()) { // a header that cannot be right: the stream is out of step
                used = m_buffer.size();
                break;
            }
            if (!*cut)
                break;
            frame = rest.first((*cut)->size);
            reply = onAdu(frame, t);
        }
        used += frame.size();
        if (!reply)
            continue;
        reply->frame.assign(frame.begin(), frame.end());
        if (offerReply(result, std::move(*reply)))
            break;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(used));
    return result;
}

void Dsp408Adapter::resetFraming()
{
    m_buffer.clear();
}

} // namespace vt::dev::access
