#include "sim/dsp408_server.h"

#include <algorithm>
#include <array>
#include <utility>

namespace vt::dev::sim {

using dsp408::TelegramType;

Dsp408Server::Dsp408Server(Dsp408Device &device, dsp408::Options layout)
    : m_device(device), m_layout(layout)
{
    if (!m_layout.telegramType)
        m_layout.telegramType = TelegramType::PkwAndPzd;
}

std::size_t Dsp408Server::imageSize() const
{
    return m_layout.telegramType == TelegramType::PzdOnly ? dsp408::kPzdSize
                                                          : dsp408::kTelegram1Size;
}

void Dsp408Server::receive(std::span<const std::uint8_t> bytes)
{
    m_in.insert(m_in.end(), bytes.begin(), bytes.end());
    const std::size_t size = imageSize();
    std::size_t used = 0;
    while (m_in.size() - used >= size) {
        exchange(std::span<const std::uint8_t>(m_in).subspan(used, size));
        used += size;
    }
    m_in.erase(m_in.begin(), m_in.begin() + static_cast<std::ptrdiff_t>(used));
}

std::vector<std::uint8_t> Dsp408Server::drain()
{
    return std::exchange(m_out, {});
}

void Dsp408Server::exchange(std::span<const std::uint8_t> image)
{
    dsp408::Options in = m_layout;
    in.direction = dsp408::Direction::Request;
    dsp408::Options out = m_layout;
    out.direction = dsp408::Direction::Response;

    const bool withPkw = m_layout.telegramType == TelegramType::PkwAndPzd;
    const auto pzdBytes = withPkw ? image.subspan(dsp408::kPkwSize) : image;
    auto pzd = dsp408::decodePzdSetpoint(pzdBytes, in);
    if (!pzd.ok())
        return; // cannot happen for a whole image; never answer garbage

    dsp408::ResponseTelegram response;
    if (withPkw) {
        const auto pkwBytes = image.first(dsp408::kPkwSize);
        auto pkw = dsp408::decodePkw(pkwBytes, in);
        if (pkw.ok()) {
            response.pkw = m_device.handlePkw(*pkw);
        } else {
            // An AK the manual does not define (4..9 reserved, 12..15): decode the layout with
            // AK 0 to learn IND and PNU, and refuse with "18 other errors" (§4.6).
            std::array<std::uint8_t, dsp408::kPkwSize> copy{};
            std::copy(pkwBytes.begin(), pkwBytes.end(), copy.begin());
            copy[0] &= 0x0F; // PKE bits 15..12 = AK
            auto layout = dsp408::decodePkw(copy, in);
            response.pkw = layout.ok() ? m_device.unknownRequest(layout->ind, layout->pnu)
                                       : m_device.unknownRequest(0, 0);
        }
    }
    response.pzd = m_device.handlePzd(*pzd);
    auto bytes = dsp408::encodeTelegram(response, out);
    if (!bytes.ok())
        return;
    m_out.insert(m_out.end(), bytes->begin(), bytes->end());
    ++m_exchanges;
}

} // namespace vt::dev::sim
