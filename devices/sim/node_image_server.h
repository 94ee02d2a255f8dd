// NodeImageServer: a simulated HCS node as a PLC sees it over TCP — fixed-length process images
// exchanged cyclically (ARCHITECTURE.md "Protocol decisions", the *node image* link). Every
// `outputBytes` bytes the master sends are one output image holding a gateway telegram (CMD 3 /
// 6 / 15) padded with whatever follows; the node's answer is one input image of `inputBytes`
// bytes (the telegram, zero-padded). The node rules apply: an image equal to the previous one
// gets no answer (toggle TADR), CMD 15 answers module by module, a CMD 15 telegram longer than
// the output image gets exception 9 (HcsNode).
// Owner: the simulator front end / SimLink; single-threaded.
#pragma once

#include "core/byte_server.h"
#include "sim/hcs_answer_queue.h"
#include "sim/hcs_node.h"

#include <cstddef>

namespace vt::dev::sim {

struct NodeImageLayout
{
    // DMA Profinet manual §4.5.4: the "IN/OUT 42 byte" GSDML module serves every fold.
    std::size_t outputBytes = 42; // PLC → node
    std::size_t inputBytes = 42;  // node → PLC
};

// OPAT: 43 bytes, the CMD 15 telegram of a master with 7 slaves (OPAT manual §3.1); DMA: 42.
NodeImageLayout defaultImageLayout(hcs::Family family);

class NodeImageServer : public ByteServer
{
public:
    // The clock and the node must outlive the server. The node's output buffer limit is set to
    // the layout's output image.
    NodeImageServer(SimClock &clock, HcsNode &node, NodeImageLayout layout);
    NodeImageServer(SimClock &clock, HcsNode &node);

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;

    const NodeImageLayout &layout() const { return m_layout; }
    std::size_t imagesReceived() const { return m_images; }
    std::size_t imagesAnswered() const { return m_answered; }
    std::optional<std::int64_t> nextAnswerUs() const { return m_answers.nextReadyUs(); }
    // A new connection: drop a partial image and queued answers; the next image is answered.
    void reset();

private:
    SimClock &m_clock;
    HcsNode &m_node;
    NodeImageLayout m_layout;
    Bytes m_buffer;
    AnswerQueue m_answers;
    std::size_t m_images = 0;
    std::size_t m_answered = 0;
};

} // namespace vt::dev::sim
