// ByteServer: the device side of an in-process link. A simulator front end (Modbus RTU, node
// image, HART, CANopen) implements it; SimLink (transports/) feeds it what the master sends and
// forwards what it answers, so the simulator is "just another link" (STYLE.md rule 8).
// Not thread-safe: one link drives one server from one thread.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev {

class ByteServer
{
public:
    virtual ~ByteServer() = default;

    // Bytes from the master, in the chunks they arrived in (a frame may be split or several
    // frames may come at once, as on a real wire).
    virtual void receive(std::span<const std::uint8_t> bytes) = 0;
    // Everything the device has sent since the last call, in order.
    virtual std::vector<std::uint8_t> drain() = 0;
};

} // namespace vt::dev
