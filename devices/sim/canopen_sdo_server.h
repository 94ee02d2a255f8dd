// CanopenSdoServer: the SDO server of one simulated CANopen node as a ByteServer carrying Linux
// SocketCAN `struct can_frame` images (16 bytes each, canopen/can_frame.h), the same bytes the
// fd-based CAN link reads and writes. It serves expedited upload (read) and download (write) on
// the default SDO channel — request 0x600 + node, response 0x580 + node (CiA 301 §7.3.3,
// ARCHITECTURE.md "CAN") — against an ObjectDictionary; refusals, segmented and block transfers
// are answered with the CiA 301 abort codes. Other CAN ids are ignored, client aborts end nothing
// (no transfer is ever open). Owner: whoever builds the simulator; single-threaded. The object
// dictionary must outlive the server.
#pragma once

#include "canopen/sdo.h"
#include "core/byte_server.h"
#include "sim/object_dictionary.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev::sim {

class CanopenSdoServer : public ByteServer
{
public:
    CanopenSdoServer(ObjectDictionary &objects, std::uint8_t node);

    void receive(std::span<const std::uint8_t> bytes) override;
    std::vector<std::uint8_t> drain() override;

    // One SDO request → its response (what receive() does per frame, without the CAN layer).
    canopen::Sdo serve(const canopen::Sdo &request);

    std::uint8_t node() const { return m_node; }
    std::size_t requestsServed() const { return m_served; }
    std::size_t framesIgnored() const { return m_ignored; } // other ids, RTR, error and FD frames

private:
    void frame(std::span<const std::uint8_t> image);
    void send(const canopen::Sdo &response);

    ObjectDictionary &m_objects;
    std::uint8_t m_node;
    std::vector<std::uint8_t> m_in;
    std::vector<std::uint8_t> m_out;
    std::size_t m_served = 0;
    std::size_t m_ignored = 0;
};

} // namespace vt::dev::sim
