#include "modbus_adapter.h"

#include "access/hcs_rows.h"
#include "access/wire_value.h"
#include "modbus/exceptions.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"

namespace vt::dev::access {

namespace {

constexpr std::uint16_t kVersId = 0;  // OPAT manual §4 / DMA manuals: "Vers", raw = version × 100
constexpr std::uint16_t kModeId = 95; // E00, the mode of the module

// The function code of the answer to `t` (not Raw): FC 6 echoes a write, FC 3 answers the rest.
std::uint8_t answerFunction(const Transaction &t)
{
    return t.kind == TransactionKind::Write ? modbus::kFcWriteSingleRegister
                                            : modbus::kFcReadHoldingRegisters;
}

} // namespace

std::uint8_t ModbusPduAdapter::unitOf(const Transaction &t) const
{
    return m_fixedUnit ? *m_fixedUnit : static_cast<std::uint8_t>(t.module & 0xFF);
}

std::vector<Transaction> ModbusPduAdapter::planRead(int module,
                                                    std::span<const ParamMeta *const> rows) const
{
    return planHcsReads(module, rows);
}

std::vector<Transaction> ModbusPduAdapter::planIdentify(int module) const
{
    return planHcsIdentify(module);
}

std::optional<modbus::RequestPdu> ModbusPduAdapter::requestPdu(const Transaction &t) const
{
    switch (t.kind) {
    case TransactionKind::Identify: return modbus::ReadRequest{t.step == 0 ? kVersId : kModeId, 1};
    case TransactionKind::Read: {
        if (t.rows.empty() || !t.rows.front()->id || t.rows.size() > modbus::kMaxReadRegisters)
            return std::nullopt;
        return modbus::ReadRequest{static_cast<std::uint16_t>(*t.rows.front()->id),
                                   static_cast<std::uint16_t>(t.rows.size())};
    }
    case TransactionKind::Write: {
        if (t.rows.size() != 1 || t.values.size() != 1 || !t.rows.front()->id)
            return std::nullopt;
        // Range of the row's type, not just of a register: 65535 for an int16 row would arrive as
        // -1.
        const auto word = hcsWordOf(*t.rows.front(), t.values.front());
        if (!word)
            return std::nullopt;
        return modbus::WriteRequest{static_cast<std::uint16_t>(*t.rows.front()->id), *word};
    }
    case TransactionKind::Raw: break;
    }
    return std::nullopt;
}

Reply ModbusPduAdapter::replyFromPdu(const Transaction &t, std::uint8_t unit,
                                     const modbus::ResponsePdu &pdu) const
{
    Reply reply;
    if (t.kind != TransactionKind::Raw && unit != unitOf(t)) {
        reply.status = ReplyStatus::Mismatch;
        return reply;
    }
    if (const auto *exception = std::get_if<modbus::ExceptionResponse>(&pdu)) {
        if (t.kind != TransactionKind::Raw && exception->function != answerFunction(t)) {
            reply.status = ReplyStatus::Mismatch;
            return reply;
        }
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionCode = exception->code;
        reply.exceptionText = modbus::exceptionText(exception->function, exception->code, m_family);
        return reply;
    }
    switch (t.kind) {
    case TransactionKind::Identify: {
        const auto *read = std::get_if<modbus::ReadResponse>(&pdu);
        if (!read || read->registers.size() != 1)
            break;
        if (t.step == 0)
            reply.identity.versRaw = read->registers.front();
        else
            reply.identity.mode = read->registers.front();
        reply.values.emplace_back(static_cast<double>(read->registers.front()));
        return reply;
    }
    case TransactionKind::Read: {
        const auto *read = std::get_if<modbus::ReadResponse>(&pdu);
        if (!read || read->registers.size() != t.rows.size())
            break;
        for (std::size_t i = 0; i < t.rows.size(); ++i)
            reply.values.emplace_back(registerToRaw(*t.rows[i], read->registers[i]));
        return reply;
    }
    case TransactionKind::Write: {
        const auto *write = std::get_if<modbus::WriteResponse>(&pdu);
        const auto request = requestPdu(t);
        const auto *asked = request ? std::get_if<modbus::WriteRequest>(&*request) : nullptr;
        if (!write || !asked || write->address != asked->address || write->value != asked->value)
            break;
        reply.values.emplace_back(registerToRaw(*t.rows.front(), write->value));
        return reply;
    }
    case TransactionKind::Raw: return reply;
    }
    reply.status = ReplyStatus::Mismatch;
    return reply;
}

std::size_t ModbusPduAdapter::responsePduBytes(const Transaction &t)
{
    switch (t.kind) {
    case TransactionKind::Identify: return 4;
    case TransactionKind::Read: return 2 + 2 * t.rows.size();
    case TransactionKind::Write: return 5;
    case TransactionKind::Raw: break;
    }
    return modbus::kMaxPduSize;
}

// --- RTU -------------------------------------------------------------------------------------

Bytes ModbusRtuAdapter::encode(const Transaction &t)
{
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    const auto pdu = requestPdu(t);
    if (!pdu || unitOf(t) == 0) // unit 0: the broadcast, never answered
        return {};
    auto bytes = modbus::encodeRtu(modbus::RtuRequest{unitOf(t), *pdu});
    return bytes ? std::move(*bytes) : Bytes{};
}

std::size_t ModbusRtuAdapter::expectedReplyBytes(const Transaction &t) const
{
    return modbus::kRtuOverhead + responsePduBytes(t);
}

std::optional<Reply> ModbusRtuAdapter::feed(std::span<const std::uint8_t> bytes,
                                            const Transaction &t)
{
    std::optional<Reply> result;
    for (Bytes &frame : m_deframer.feed(bytes)) {
        auto decoded = modbus::decodeRtuResponse(frame);
        if (!decoded)
            continue;
        Reply reply = replyFromPdu(t, decoded->unit, decoded->pdu);
        reply.frame = std::move(frame);
        if (offerReply(result, std::move(reply)))
            break;
    }
    return result;
}

void ModbusRtuAdapter::resetFraming()
{
    m_deframer.silence();
}

// Modbus over Serial Line §2.5.1.1 ends a frame at t3.5 of silence and drops an incomplete one.
// A PC does not see the line's byte timing, only when its driver hands bytes on: a USB adapter's
// latency timer (16 ms by default on FTDI chips) or a busy scheduler puts a gap into the middle
// of an answer that was whole on the wire. So a quiet keeps bytes that are the start of exactly
// the answer awaited (its unit, function code and byte count) and lets its CRC decide when the
// rest arrives; whatever else is buffered can never become a frame and is dropped.
void ModbusRtuAdapter::lineQuiet(const Transaction *onTheWire)
{
    if (onTheWire && startsAnswerTo(m_deframer.pending(), *onTheWire))
        return;
    m_deframer.silence();
}

bool ModbusRtuAdapter::startsAnswerTo(std::span<const std::uint8_t> bytes,
                                      const Transaction &t) const
{
    if (bytes.empty() || t.kind == TransactionKind::Raw || bytes.size() >= expectedReplyBytes(t))
        return false;
    if (bytes[0] != unitOf(t))
        return false;
    if (bytes.size() < 2)
        return true;
    const std::uint8_t function = answerFunction(t);
    if (bytes[1] == (function | modbus::kExceptionBit))
        return bytes.size() < modbus::kRtuOverhead + 2; // an exception: unit, fc, code, CRC
    if (bytes[1] != function)
        return false;
    // A read's answer announces its byte count in its third byte.
    return function != modbus::kFcReadHoldingRegisters || bytes.size() < 3 ||
           bytes[2] == responsePduBytes(t) - 2;
}

// --- TCP -------------------------------------------------------------------------------------

Bytes ModbusTcpAdapter::encode(const Transaction &t)
{
    m_outstanding = m_nextTransaction++;
    if (m_nextTransaction == 0)
        m_nextTransaction = 1;
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    const auto pdu = requestPdu(t);
    if (!pdu)
        return {};
    auto bytes = modbus::encodeTcp(modbus::TcpRequest{m_outstanding, unitOf(t), *pdu});
    return bytes ? std::move(*bytes) : Bytes{};
}

std::size_t ModbusTcpAdapter::expectedReplyBytes(const Transaction &t) const
{
    return modbus::kMbapSize + responsePduBytes(t); // the MBAP header carries the unit id
}

std::optional<Reply> ModbusTcpAdapter::feed(std::span<const std::uint8_t> bytes,
                                            const Transaction &t)
{
    std::optional<Reply> result;
    for (Bytes &frame : m_deframer.feed(bytes)) {
        auto decoded = modbus::decodeTcpResponse(frame);
        if (!decoded)
            continue;
        Reply reply;
        if (t.kind != TransactionKind::Raw && decoded->transaction != m_outstanding)
            reply.status = ReplyStatus::Mismatch; // a late answer to an earlier attempt
        else
            reply = replyFromPdu(t, decoded->unit, decoded->pdu);
        reply.frame = std::move(frame);
        if (offerReply(result, std::move(reply)))
            break;
    }
    if (m_deframer.error())
        m_deframer.reset(); // out of step: the session's retry starts from a clean stream
    return result;
}

void ModbusTcpAdapter::resetFraming()
{
    m_deframer.reset();
}

} // namespace vt::dev::access
