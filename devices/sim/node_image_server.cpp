#include "sim/node_image_server.h"

#include <algorithm>

namespace vt::dev::sim {

NodeImageLayout defaultImageLayout(hcs::Family family)
{
    if (family == hcs::Family::Opat)
        return {43, 43};
    return {};
}

NodeImageServer::NodeImageServer(SimClock &clock, HcsNode &node, NodeImageLayout layout)
    : m_clock(clock), m_node(node), m_layout(layout)
{
    m_layout.outputBytes = std::max<std::size_t>(m_layout.outputBytes, 1);
    HcsNodeOptions options = m_node.options();
    options.outputBufferBytes = m_layout.outputBytes;
    m_node.setOptions(options);
}

NodeImageServer::NodeImageServer(SimClock &clock, HcsNode &node)
    : NodeImageServer(clock, node, defaultImageLayout(node.family()))
{
}

void NodeImageServer::receive(std::span<const std::uint8_t> bytes)
{
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::size_t used = 0;
    while (m_buffer.size() - used >= m_layout.outputBytes) {
        const auto image =
            std::span<const std::uint8_t>(m_buffer).subspan(used, m_layout.outputBytes);
        used += m_layout.outputBytes;
        ++m_images;
        auto answer = m_node.process(image);
        if (!answer)
            continue;
        ++m_answered;
        // The input image: the telegram, zero-padded (or cut, should the PLC's input image be
        // shorter than a CMD 3 answer — a configuration error the real node would show the same
        // way).
        answer->bytes.resize(m_layout.inputBytes, 0);
        m_answers.push(std::move(*answer));
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(used));
}

std::vector<std::uint8_t> NodeImageServer::drain()
{
    return m_answers.take(m_clock.nowUs());
}

void NodeImageServer::reset()
{
    m_buffer.clear();
    m_answers.clear();
    m_node.resetChangeDetection();
}

} // namespace vt::dev::sim
