// HartServer: the byte-stream front end of a simulated HART field device (ByteServer, so an
// in-process link or a serial line can carry it). Bytes go through the HART de-framer
// (hart/deframer.h, HART-7 manual §2.3); each whole request frame goes to the HartDevice and its
// response is encoded with the device's response preambles. Frames with a bad checksum or an
// impossible layout are dropped without an answer: the manual names no communication-error reply
// (§4.4.1 lists status codes 0, 5 and 6 only), and a slave cannot trust the address of a broken
// frame. Owner: whoever builds the simulator; single-threaded. The device must outlive the server.
#pragma once

#include "core/byte_server.h"
#include "hart/deframer.h"
#include "sim/hart_device.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev::sim {

class HartServer : public ByteServer
{
public:
    explicit HartServer(HartDevice &device);

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;
    // End of a burst of bytes (the line went quiet): an incomplete frame is given up.
    void gap();

    std::size_t framesAnswered() const { return m_answered; }
    std::size_t framesIgnored() const { return m_ignored; }   // not addressed to this device
    std::size_t framesRejected() const { return m_rejected; } // checksum, layout, truncation

private:
    void handle(const std::vector<hart::DeframerEvent> &events);

    HartDevice &m_device;
    hart::Deframer m_deframer;
    std::vector<std::uint8_t> m_out;
    std::size_t m_answered = 0;
    std::size_t m_ignored = 0;
    std::size_t m_rejected = 0;
};

} // namespace vt::dev::sim
