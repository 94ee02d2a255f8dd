// CMD 15, the node's fast multi-module telegram: set values and control bytes for every module
// in one request, one module's status word and two actual values per response (multiplexed).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"
#include "types.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::hcs {

// One module's share of the request: DATx.1 (control byte, "byte for special functions"),
// DATx.2 (VALUE1) and DATx.3 (VALUE2), signed 16-bit (OPAT manual §3.1: 0x8000 == -32768).
struct ModuleSetpoints
{
    std::uint8_t control = 0;
    std::int16_t value1 = 0;
    std::int16_t value2 = 0;

    bool operator==(const ModuleSetpoints &) const = default;
};

// Request: TADR SNUM 15 then 5 bytes per module (OPAT manual §3.1, DMA Profinet manual §4.1).
// SNUM is not stored: it follows from the module count and the family (snumForModules).
struct CyclicRequest
{
    std::uint8_t tadr = 0;
    std::vector<ModuleSetpoints> modules; // modules[0] = OPAT master (SADR 0) / DMA module E22 = 1

    bool operator==(const CyclicRequest &) const = default;
};

// Response (9 bytes): TADR SADR 15, status word DAT.1, VALUE1 DAT.2, VALUE2 DAT.3
// (OPAT manual §3.2, DMA Profinet manual §4.2). SADR names the module that answered.
struct CyclicResponse
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::uint16_t status = 0;
    std::int16_t value1 = 0;
    std::int16_t value2 = 0;

    bool operator==(const CyclicResponse &) const = default;
};

// OPAT manual §3.1: "SNUM Number of connected OPAT-Slaves (Maximum 7). The OPAT-Master (SADR = 0)
// is always included" → modules = SNUM + 1 (1..8, telegram 8..43 bytes).
// DMA Profinet manual §4.1: "SNUM Number of connected slaves (Maximum 5)" → modules = SNUM (1..5,
// telegram 8..28 bytes). Returns nullopt for an SNUM the family does not allow.
std::optional<std::size_t> modulesForSnum(Family family, std::uint8_t snum);
std::optional<std::uint8_t> snumForModules(Family family, std::size_t modules);
std::size_t maxCyclicModules(Family family); // 8 (OPAT) / 5 (DMA)
// Module address (SADR / E22) of modules[index]: OPAT 0 = master, 1..7 slaves; DMA 1..5.
std::uint8_t moduleAddress(Family family, std::size_t index);

// Fails (BadValue) when the module count does not fit the family.
Result<Bytes, DecodeError> encode(const CyclicRequest &request, Family family);
Bytes encode(const CyclicResponse &response);

// CMD must be 15; BadValue at offset 1 for an SNUM the family does not allow.
Result<CyclicRequest, DecodeError> decodeCyclicRequest(std::span<const std::uint8_t> frame,
                                                       const DecodeOptions &options = {});
// An error frame (0x8F) gives DecodeErrc::DeviceException with deviceCode = EXCE.
Result<CyclicResponse, DecodeError> decodeCyclicResponse(std::span<const std::uint8_t> frame,
                                                         const DecodeOptions &options = {});

} // namespace vt::dev::hcs
