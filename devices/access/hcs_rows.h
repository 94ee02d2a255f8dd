// What every HCS adapter (Modbus RTU, Modbus TCP, node image, CANopen 0x2000 + ID) shares: the
// read plan in blocks of consecutive IDs, the identify plan, and the 16-bit register <-> raw value
// conversion by the row's type. HCS parameters are 16-bit words addressed by ID (OPAT manual §2.1).
#pragma once

#include "access/transaction.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"
#include "hcs/types.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace vt::dev::access {

struct HcsBlock
{
    std::uint16_t firstId = 0;
    std::vector<const ParamMeta *> rows; // consecutive IDs firstId, firstId + 1, …
};

// Readable rows with an ID, sorted by ID, cut into runs of consecutive IDs of at most
// `maxPerBlock` (OPAT manual §2.1 / DMA Profinet manual §3.1: "maximal 8 parameters readable at
// once"). A gap in the IDs (an inactive or unknown row) starts a new block: it is never read.
std::vector<HcsBlock> planHcsBlocks(std::span<const ParamMeta *const> rows,
                                    std::uint16_t maxPerBlock = hcs::kMaxReadCount);
// One read transaction per block of planHcsBlocks.
std::vector<Transaction> planHcsReads(int module, std::span<const ParamMeta *const> rows,
                                      std::uint16_t maxPerBlock = hcs::kMaxReadCount);
// An HCS module identifies itself by two reads: step 0 Vers (ID 0), step 1 E00.
std::vector<Transaction> planHcsIdentify(int module);

// The register as the row's type reads it (int16 and int8 sign-extended).
double registerToRaw(const ParamMeta &row, std::uint16_t word);
// The raw value as a register (two's complement for negative values); nullopt when the value
// is text, not integral or does not fit 16 bits.
std::optional<std::uint16_t> rawToRegister(const RawValue &value);

// "opat…" → Opat, everything else HCS → Dma (exception tables differ: hcs/exceptions.h).
hcs::Family hcsFamilyOf(std::string_view dictionaryFamily);

} // namespace vt::dev::access
