// HCS modules through the node's gateway telegrams as a PLC exchanges them over TCP — the *node
// image* link (ARCHITECTURE.md "Over TCP"): CMD 3 reads ≤ 8 consecutive IDs, CMD 6 writes one,
// each request in a fixed-length output image, each answer in a fixed-length input image.
// Owner: one session; single-threaded.
#pragma once

#include "access/transaction.h"
#include "hcs/types.h"

#include <cstddef>
#include <cstdint>

namespace vt::dev::access {

// The PLC's process images: every `outputBytes` bytes sent are one request telegram padded with
// zeros, every `inputBytes` bytes received are one answer telegram followed by padding. DMA
// Profinet manual §4.5.4: the "IN/OUT 42 byte" module serves every fold; the OPAT needs 43, the
// CMD 15 telegram of a master with 7 slaves (OPAT manual §3.1). Must match the node's GSD module.
struct NodeImageLayout
{
    std::size_t outputBytes = 42; // PLC → node
    std::size_t inputBytes = 42;  // node → PLC
};

NodeImageLayout defaultNodeImageLayout(hcs::Family family);

class NodeImageAdapter : public ProtocolAdapter
{
public:
    explicit NodeImageAdapter(hcs::Family family);
    NodeImageAdapter(hcs::Family family, NodeImageLayout layout);

    LinkProtocol protocol() const override { return LinkProtocol::NodeImage; }

    // Blocks of ≤ 8 consecutive IDs (fewer when the input image cannot hold 8 values).
    std::vector<Transaction> planRead(int module,
                                      std::span<const ParamMeta *const> rows) const override;
    // Step 0: CMD 3 of Vers (ID 0); step 1: CMD 3 of E00 (ID 95).
    std::vector<Transaction> planIdentify(int module) const override;

    // One output image. Every call takes the next TADR (OPAT manual §1.5 / DMA Profinet manual
    // §1.4: the node answers only a request whose bytes changed — a retry must differ too).
    // Empty for a module outside 0..255, a row without ID, a text or out-of-range value.
    Bytes encode(const Transaction &t) override;
    // One input image.
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    // Cuts the stream into input images. An image answers `t` when TADR, SADR and CMD (or the
    // error frame CMD | 0x80) are the request's and the count / echo fits; an all-zero image is
    // idle. An image that is no node answer at all means lost alignment (resetFraming() dropped
    // part of an image): the stream is searched byte by byte until the answer to `t` is found.
    // The telegrams carry no checksum (TCP does): a changed value byte cannot be detected.
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;

    const NodeImageLayout &layout() const { return m_layout; }
    // TADR of the last encoded request.
    std::uint8_t lastTadr() const { return m_tadr; }

private:
    std::optional<Reply> imageReply(std::span<const std::uint8_t> image,
                                    const Transaction &t) const;

    hcs::Family m_family;
    NodeImageLayout m_layout;
    std::uint8_t m_tadr = 0; // incremented before each request: the first one carries 1
    Bytes m_buffer;          // received bytes not yet consumed as a whole input image
    bool m_resync = false;   // out of step: hunting byte by byte for the answer's image
};

} // namespace vt::dev::access
