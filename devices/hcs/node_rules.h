// The node's own limits (≤ 8 parameters per read, address ranges, CNT ≤ 16), kept apart from the
// codecs so that those accept any well-formed telegram; the session and the simulator ask here.
#pragma once

#include "core/local_text.h"
#include "telegram.h"
#include "types.h"

#include <cstdint>
#include <vector>

namespace vt::dev::hcs {

// OPAT manual §2.1 / DMA Profinet manual §3.1: "N-low … 1 to 8 (maximal 8 parameters readable at
// once)".
constexpr bool withinReadLimit(std::uint32_t count)
{
    return count >= 1 && count <= kMaxReadCount;
}

struct ReadBlock
{
    std::uint16_t firstId = 0;
    std::uint16_t count = 0;

    bool operator==(const ReadBlock &) const = default;
};

// Splits a read of `count` consecutive IDs into blocks of at most `maxPerBlock` (default: the
// node's 8; a Modbus peer without the HCS rule may allow up to 125). Stops at ID 0xFFFF.
std::vector<ReadBlock> splitReads(std::uint16_t firstId, std::uint32_t count,
                                  std::uint16_t maxPerBlock = kMaxReadCount);

// Human-readable notes on everything in a well-formed telegram that the node rules forbid
// ("N = 12: the node reads 1..8 parameters at once; it answers exception 3"). Empty = fine.
std::vector<LocalText> nodeRuleNotes(const Request &request, Family family);
std::vector<LocalText> nodeRuleNotes(const Response &response, Family family);

} // namespace vt::dev::hcs
