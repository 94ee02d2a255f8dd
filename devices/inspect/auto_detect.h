// Protocol auto-detection for the inspector's decode box: which of ValveTune's protocols a bare
// byte string can be, and whether that is unambiguous. Checksums and headers (Modbus RTU CRC,
// Modbus TCP MBAP, HART preambles + XOR) are strong evidence; a frame that merely decodes
// (gateway, PROFIdrive mix, PKW, SDO) is weak evidence and decides only when it is the only one.
// A Modbus RTU frame whose length matches its header but whose CRC is wrong is named as such
// (a damaged frame is what one pastes to ask why) unless a checksum confirms another protocol.
#pragma once

#include "core/direction.h"
#include "hcs/types.h"
#include "inspect/describe_any.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::inspect {

struct Candidate
{
    FrameFormat protocol = FrameFormat::Gateway;
    bool strong = false;               // a checksum / header confirmed it
    std::vector<Direction> directions; // the directions in which the bytes decode
    std::vector<hcs::Family> families; // gateway / Modbus / PROFIdrive: families that decode
    bool badCrc = false; // Modbus RTU whose header fits its length but whose CRC is wrong
};

struct Detection
{
    std::vector<Candidate> candidates; // every protocol the bytes decode as, strong ones first
    std::optional<std::size_t> chosen; // index into candidates when the evidence is unambiguous

    const Candidate *choice() const { return chosen ? &candidates[*chosen] : nullptr; }
};

// `cobId` (from candump notation) makes it CANopen without looking further. Six-byte PZD-only
// telegrams and a bare four-byte PROFIdrive telegram 1 are never guessed: any bytes decode so.
Detection detectProtocol(std::span<const std::uint8_t> bytes,
                         std::optional<std::uint32_t> cobId = std::nullopt);

} // namespace vt::dev::inspect
