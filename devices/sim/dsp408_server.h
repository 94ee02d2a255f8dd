// Dsp408Server: the cyclic PROFIBUS-DP data exchange of a simulated ED1/SD1 as a ByteServer.
// The master side sends whole output images of the configured telegram type (ED1/SD1 manual
// §4.5.1: type 1 = 4 PKW + 3 PZD words = 14 bytes, type 2 = 3 PZD words = 6 bytes), as a PLC
// exchanges them every bus cycle; the server answers every image with one input image of the
// same type. Bytes may arrive in any chunks; a partial image waits for the rest.
// Owner: whoever builds the simulator; single-threaded. The device must outlive the server.
#pragma once

#include "core/byte_server.h"
#include "dsp408/options.h"
#include "sim/dsp408_device.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev::sim {

class Dsp408Server : public ByteServer
{
public:
    // `layout` carries the telegram type and the byte-order settings (dsp408/options.h); an unset
    // telegram type means type 1.
    explicit Dsp408Server(Dsp408Device &device, dsp408::Options layout = {});

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;

    std::size_t imageSize() const;
    // A new master: a partial image of the previous one is dropped.
    void reset() { m_in.clear(); }
    std::size_t exchanges() const { return m_exchanges; }

private:
    void exchange(std::span<const std::uint8_t> image);

    Dsp408Device &m_device;
    dsp408::Options m_layout;
    std::vector<std::uint8_t> m_in;
    std::vector<std::uint8_t> m_out;
    std::size_t m_exchanges = 0;
};

} // namespace vt::dev::sim
