// A PROFIBUS-master gateway in front of a simulated ED1/SD1: the gateway exchanges the slave's
// cyclic images (ED1/SD1 manual §4.5.1, telegram type 1) and shows them in Modbus TCP registers
// (ARCHITECTURE.md "Wandfluh ED1/SD1 online", dsp408/gateway.h): FC 16 writes the output image
// (PKW request + PZD), FC 3 or FC 4 — as configured — reads the input image (PKW response + PZD).
// Every write and every read of the input image is one bus cycle: the output image goes to the
// device and its answer becomes the input image, as a gateway's cyclic data exchange would have
// it by the time the next Modbus request arrives.
// Dsp408GatewayImage is the gateway (one per device); Dsp408GatewayServer is one Modbus TCP
// connection to it (several clients may be connected, each de-framing its own stream).
// Owner: SimDevice; single-threaded. The image must outlive its servers, the device the image.
#pragma once

#include "core/byte_server.h"
#include "dsp408/gateway.h"
#include "dsp408/options.h"
#include "sim/dsp408_server.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace vt::dev::sim {

class Dsp408GatewayImage
{
public:
    Dsp408GatewayImage(Dsp408Device &device, dsp408::Options layout, dsp408::GatewayMap map,
                       std::uint8_t unit);

    // One Modbus PDU for this gateway → the answer PDU (exceptions included).
    Bytes handle(std::span<const std::uint8_t> pdu);
    std::uint8_t unit() const { return m_unit; }
    std::size_t cycles() const { return m_cycles; }

private:
    void busCycle();

    Dsp408Server m_slave;
    dsp408::GatewayMap m_map;
    std::uint8_t m_unit;
    std::array<std::uint16_t, dsp408::kImageRegisters> m_output{};
    std::array<std::uint16_t, dsp408::kImageRegisters> m_input{};
    std::size_t m_cycles = 0;
};

class Dsp408GatewayServer : public ByteServer
{
public:
    explicit Dsp408GatewayServer(Dsp408GatewayImage &image) : m_image(image) {}

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;
    // A new connection: drop a partial ADU and a latched framing error.
    void reset();

private:
    Dsp408GatewayImage &m_image;
    Bytes m_in;
    Bytes m_out;
    bool m_outOfStep = false;
};

} // namespace vt::dev::sim
