#include "sim/hart_server.h"

#include <utility>

namespace vt::dev::sim {

HartServer::HartServer(HartDevice &device) : m_device(device)
{
}

void HartServer::receive(std::span<const std::uint8_t> bytes)
{
    handle(m_deframer.feed(bytes));
}

void HartServer::gap()
{
    handle(m_deframer.flush());
}

std::vector<std::uint8_t> HartServer::drain()
{
    return std::exchange(m_out, {});
}

void HartServer::handle(const std::vector<hart::DeframerEvent> &events)
{
    for (const hart::DeframerEvent &event : events) {
        if (event.kind == hart::DeframerEvent::Kind::Error) {
            ++m_rejected;
            continue;
        }
        const auto response = m_device.handle(event.frame);
        if (!response) {
            ++m_ignored;
            continue;
        }
        auto bytes = hart::encodeFrame(*response);
        if (!bytes.ok()) { // a device bug, not a line problem: count it, never crash the link
            ++m_rejected;
            continue;
        }
        m_out.insert(m_out.end(), bytes->begin(), bytes->end());
        ++m_answered;
    }
}

} // namespace vt::dev::sim
