// The CAN side of valvetune-sim: a SocketCAN CAN_RAW socket bound to an interface, or an adopted
// descriptor that carries one 16-byte Linux `struct can_frame` per datagram (tests: one end of
// socketpair(AF_UNIX, SOCK_SEQPACKET), as tests/transports/can_link_test.cpp does), and the
// candump text of frames for -v. Plain POSIX; the caller owns the returned descriptor.
#pragma once

#include "app/sim/host_error.h"
#include "core/result.h"

#include <cstdint>
#include <span>
#include <string>

namespace vt::simapp {

// A non-blocking, close-on-exec CAN_RAW socket on `interfaceName` that receives only the SDO
// requests to `node` (standard data frames 0x600 + node, CiA 301 §7.3.3). Exit code 3 when this
// kernel has no SocketCAN or the interface does not exist.
dev::Result<int, HostError> openCanSocket(const std::string &interfaceName, std::uint8_t node);

// Takes over `fd`: it must be open and a socket that keeps datagram boundaries (SEQPACKET,
// DGRAM or RAW); it is made non-blocking and close-on-exec.
dev::Result<int, HostError> adoptCanFd(int fd);

// Whole 16-byte images as candump text, "601#4000200000000000", separated by spaces; an image
// that is no classic frame as its hex bytes in brackets.
std::string candumpText(std::span<const std::uint8_t> images);

} // namespace vt::simapp
