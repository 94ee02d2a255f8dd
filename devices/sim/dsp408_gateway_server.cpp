#include "sim/dsp408_gateway_server.h"

#include "modbus/exceptions.h"
#include "modbus/register_image.h"

#include <algorithm>
#include <utility>
#include <variant>

namespace vt::dev::sim {
namespace {

// Modbus Application Protocol V1.1b3 §7: 0x0B "gateway target device failed to respond".
constexpr std::uint8_t kGatewayTargetFailed = 0x0B;

Bytes exception(std::uint8_t function, std::uint8_t code)
{
    auto pdu = modbus::encodeRegisterPdu(
        modbus::RegisterResponse{modbus::RegisterException{function, code}});
    return pdu.ok() ? *pdu : Bytes{};
}

// The registers [start, start + count) of an image area at `base`, as an offset into the area.
std::optional<std::size_t> within(std::uint16_t base, std::uint16_t start, std::size_t count)
{
    if (start < base || start - base + count > dsp408::kImageRegisters)
        return std::nullopt;
    return static_cast<std::size_t>(start - base);
}

} // namespace

Dsp408GatewayImage::Dsp408GatewayImage(Dsp408Device &device, dsp408::Options layout,
                                       dsp408::GatewayMap map, std::uint8_t unit)
    : m_slave(device,
              [&] {
                  layout.telegramType = dsp408::TelegramType::PkwAndPzd;
                  return layout;
              }()),
      m_map(map), m_unit(unit)
{
}

void Dsp408GatewayImage::busCycle()
{
    const Bytes out = dsp408::fromRegisters(m_output, m_map.byteOrder);
    m_slave.receive(out);
    const Bytes in = m_slave.drain();
    if (in.size() == dsp408::kTelegram1Size) {
        const auto registers = dsp408::toRegisters(in, m_map.byteOrder);
        std::copy(registers.begin(), registers.end(), m_input.begin());
    }
    ++m_cycles;
}

Bytes Dsp408GatewayImage::handle(std::span<const std::uint8_t> pdu)
{
    const auto request = modbus::decodeRegisterRequest(pdu);
    if (!request.ok()) {
        const std::uint8_t function = pdu.empty() ? 0 : pdu.front();
        if (function == 0 || (function & modbus::kExceptionBit) != 0)
            return {};
        return exception(function, request.error().code == DecodeErrc::UnexpectedCommand
                                       ? modbus::kIllegalFunction
                                       : modbus::kIllegalDataValue);
    }
    if (const auto *write = std::get_if<modbus::RegisterWrite>(&*request)) {
        const auto at = within(m_map.outputRegister, write->start, write->values.size());
        if (!at)
            return exception(modbus::kFcWriteMultipleRegisters, modbus::kIllegalDataAddress);
        std::copy(write->values.begin(), write->values.end(),
                  m_output.begin() + static_cast<std::ptrdiff_t>(*at));
        busCycle();
        auto answer =
            modbus::encodeRegisterPdu(modbus::RegisterResponse{modbus::RegisterWriteAnswer{
                write->start, static_cast<std::uint16_t>(write->values.size())}});
        return answer.ok() ? *answer : Bytes{};
    }
    const auto &read = std::get<modbus::RegisterRead>(*request);
    modbus::RegisterReadAnswer answer{read.function, {}};
    if (read.function == static_cast<std::uint8_t>(m_map.inputFunction)) {
        if (const auto at = within(m_map.inputRegister, read.start, read.count)) {
            busCycle();
            answer.registers.assign(m_input.begin() + static_cast<std::ptrdiff_t>(*at),
                                    m_input.begin() +
                                        static_cast<std::ptrdiff_t>(*at + read.count));
        }
    }
    // The output image reads back through FC 3 (what the master last wrote).
    if (answer.registers.empty() && read.function == modbus::kFcReadHoldingRegisters) {
        if (const auto at = within(m_map.outputRegister, read.start, read.count))
            answer.registers.assign(m_output.begin() + static_cast<std::ptrdiff_t>(*at),
                                    m_output.begin() +
                                        static_cast<std::ptrdiff_t>(*at + read.count));
    }
    if (answer.registers.empty())
        return exception(read.function, modbus::kIllegalDataAddress);
    auto bytes = modbus::encodeRegisterPdu(modbus::RegisterResponse{std::move(answer)});
    return bytes.ok() ? *bytes : Bytes{};
}

void Dsp408GatewayServer::receive(std::span<const std::uint8_t> bytes)
{
    if (m_outOfStep)
        return;
    m_in.insert(m_in.end(), bytes.begin(), bytes.end());
    std::size_t used = 0;
    while (used < m_in.size()) {
        const auto cut = modbus::cutAdu(std::span<const std::uint8_t>(m_in).subspan(used));
        if (!cut.ok()) {
            m_outOfStep = true; // as ModbusTcpServer: nothing more until the client reconnects
            m_in.clear();
            return;
        }
        if (!*cut)
            break;
        const modbus::AduCut &adu = **cut;
        used += adu.size;
        Bytes pdu = adu.header.unit == m_image.unit()
                        ? m_image.handle(adu.pdu)
                        : exception(adu.pdu.empty() ? 0 : adu.pdu.front(), kGatewayTargetFailed);
        if (pdu.empty())
            continue;
        const Bytes frame = modbus::wrapAdu(adu.header.transaction, adu.header.unit, pdu);
        m_out.insert(m_out.end(), frame.begin(), frame.end());
    }
    m_in.erase(m_in.begin(), m_in.begin() + static_cast<std::ptrdiff_t>(used));
}

std::vector<std::uint8_t> Dsp408GatewayServer::drain()
{
    return std::exchange(m_out, {});
}

void Dsp408GatewayServer::reset()
{
    m_in.clear();
    m_outOfStep = false;
}

} // namespace vt::dev::sim
