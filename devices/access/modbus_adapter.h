// HCS modules over Modbus (ARCHITECTURE.md "Protocol decisions"): CMD 3 = FC 3 read holding
// registers (register = parameter ID, ≤ 8 per request), CMD 6 = FC 6, exceptions FC | 0x80 with
// the HCS meaning of the code. ModbusRtuAdapter frames with unit id + CRC (serial line),
// ModbusTcpAdapter with the MBAP header and a transaction number per attempt.
#pragma once

#include "access/transaction.h"
#include "hcs/types.h"
#include "modbus/deframer.h"
#include "modbus/pdu.h"

#include <cstdint>

namespace vt::dev::access {

// The protocol-independent half: PDUs from transactions and replies from PDUs.
class ModbusPduAdapter : public ProtocolAdapter
{
public:
    explicit ModbusPduAdapter(hcs::Family family,
                              std::optional<std::uint8_t> fixedUnit = std::nullopt)
        : m_family(family), m_fixedUnit(fixedUnit)
    {
    }

    std::vector<Transaction> planRead(int module,
                                      std::span<const ParamMeta *const> rows) const override;
    std::vector<Transaction> planIdentify(int module) const override;

protected:
    // nullopt for a transaction this protocol cannot express (a text value, a row without ID).
    std::optional<modbus::RequestPdu> requestPdu(const Transaction &t) const;
    // The reply to `t` carried by `pdu` from unit `unit`.
    Reply replyFromPdu(const Transaction &t, std::uint8_t unit,
                       const modbus::ResponsePdu &pdu) const;
    // FC 3 response: 1 + 1 + 2 × count; FC 6 and exceptions are shorter.
    static std::size_t responsePduBytes(const Transaction &t);
    // The unit id a request for `t` goes to.
    std::uint8_t unitOf(const Transaction &t) const;

private:
    hcs::Family m_family;
    std::optional<std::uint8_t> m_fixedUnit;
};

class ModbusRtuAdapter : public ModbusPduAdapter
{
public:
    // ARCHITECTURE.md "Protocol decisions": on RS485 the unit id is the module address (E22); on
    // a point-to-point line it is configurable (`pointToPointUnit`, usually 1) and every request
    // goes to it whatever the module (the OPAT master, SADR 0, would otherwise be unit 0).
    // Without it a request to module 0 is not encoded: unit 0 is the Modbus broadcast, which no
    // device answers (Modbus over Serial Line §2.2).
    explicit ModbusRtuAdapter(hcs::Family family,
                              std::optional<std::uint8_t> pointToPointUnit = std::nullopt)
        : ModbusPduAdapter(family, pointToPointUnit)
    {
    }

    LinkProtocol protocol() const override { return LinkProtocol::ModbusRtu; }
    Bytes encode(const Transaction &t) override;
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;
    // Drops what is buffered, except the start of the answer to `onTheWire` (see the .cpp).
    void lineQuiet(const Transaction *onTheWire) override;

private:
    // `bytes` can still become the answer to `t` (a proper prefix of its expected layout).
    bool startsAnswerTo(std::span<const std::uint8_t> bytes, const Transaction &t) const;

    modbus::RtuDeframer m_deframer{Direction::Response};
};

class ModbusTcpAdapter : public ModbusPduAdapter
{
public:
    using ModbusPduAdapter::ModbusPduAdapter;

    LinkProtocol protocol() const override { return LinkProtocol::ModbusTcp; }
    // Each call numbers a new transaction (Implementation Guide §4.1.2): a late answer to an
    // earlier attempt is recognised by its number and ignored.
    Bytes encode(const Transaction &t) override;
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;

private:
    modbus::TcpDeframer m_deframer;
    std::uint16_t m_nextTransaction = 1;
    std::uint16_t m_outstanding = 0;
};

} // namespace vt::dev::access
