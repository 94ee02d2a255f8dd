// The ED1/SD1's cyclic PROFIBUS-DP images as a PROFIBUS-master gateway shows them in Modbus TCP
// registers (ARCHITECTURE.md "Wandfluh ED1/SD1 online"): the output image (PKW request + PZD,
// ED1/SD1 manual §4.5.1 telegram type 1, 7 words) written with FC 16, the input image (PKW
// response + PZD) read with FC 3 or FC 4. Where the images sit and how a register holds two
// image bytes is the gateway's configuration, so every part of the mapping is a setting.
// Pure functions and plain values; any thread.
#pragma once

#include "core/byte_writer.h"
#include "core/field_span.h"
#include "dsp408/options.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev::dsp408 {

// Register offsets of the image words (telegram type 1, §4.5.1: PKW words 1..4, PZD 001 control
// / status word, PZD 012 / 003 set / actual value in two words).
inline constexpr std::uint16_t kImageRegisters = 7;
inline constexpr std::uint16_t kPkwRegisters = 4;
inline constexpr std::uint16_t kControlWordRegister = 4; // relative to the output image
inline constexpr std::uint16_t kSetpointRegister = 5;    // two registers

// How a register holds two image bytes. Modbus registers are big-endian (Modbus Application
// Protocol §4.2), so a gateway that copies the image byte for byte puts the first byte high;
// some gateways swap each pair.
enum class RegisterByteOrder : std::uint8_t { FirstByteHigh, FirstByteLow };

// The function that reads the input image: holding registers (FC 3) or input registers (FC 4).
enum class InputFunction : std::uint8_t { HoldingRegisters = 3, InputRegisters = 4 };

struct GatewayMap
{
    // Our defaults, not a vendor's: set them to the gateway's configuration.
    std::uint16_t outputRegister = 1024; // first register of the output image (FC 16)
    std::uint16_t inputRegister = 0;     // first register of the input image
    InputFunction inputFunction = InputFunction::HoldingRegisters;
    RegisterByteOrder byteOrder = RegisterByteOrder::FirstByteHigh;

    bool operator==(const GatewayMap &) const = default;
};

// Image bytes ↔ registers (an odd byte count is padded with 0).
std::vector<std::uint16_t> toRegisters(std::span<const std::uint8_t> image,
                                       RegisterByteOrder order);
Bytes fromRegisters(std::span<const std::uint16_t> registers, RegisterByteOrder order);

// Describes one Modbus TCP ADU of a gateway exchange (options.direction: request = PC →
// gateway): the MBAP header and function, then the image part it carries — a write of 4
// registers is the PKW request, 7 the whole output image, 1 the control word, 2 the set value; a
// read answer of 7 registers is the input image (PKW response + PZD). The parts are recognised
// by their size, so the description needs no register offsets.
Description describeGatewayAdu(std::span<const std::uint8_t> adu, const Options &options,
                               RegisterByteOrder order = RegisterByteOrder::FirstByteHigh);

} // namespace vt::dev::dsp408
