// CAN endpoint helpers: see can_socket.h.
#include "can_socket.h"

#include "app/cli/exit_codes.h"
#include "canopen/can_frame.h"
#include "canopen/sdo.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

namespace vt::simapp {
namespace {

static_assert(sizeof(can_frame) == dev::canopen::kSocketCanFrameSize);

HostError ioError(const std::string &what, int error)
{
    return HostError{cli::kExitConnection, what + ": " + std::strerror(error)};
}

} // namespace

dev::Result<int, HostError> openCanSocket(const std::string &interfaceName, std::uint8_t node)
{
    const std::string what = "cannot open CAN interface " + interfaceName;
    const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) {
        const int error = errno;
        if (error == EAFNOSUPPORT || error == EPROTONOSUPPORT || error == EINVAL)
            return HostError{cli::kExitConnection,
                             what + ": SocketCAN is not available in this kernel (" +
                                 std::strerror(error) + ")"};
        return ioError(what, error);
    }
    const unsigned index = ::if_nametoindex(interfaceName.c_str());
    if (index == 0) {
        ::close(fd);
        return HostError{cli::kExitConnection, what + ": no such network interface"};
    }
    // Only our SDO requests: standard data frames with id 0x600 + node (no RTR, no 29-bit ids).
    can_filter filter{};
    filter.can_id = dev::canopen::sdoRequestId(node);
    filter.can_mask = CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_SFF_MASK;
    sockaddr_can address{};
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, &filter, sizeof filter) != 0 ||
        ::bind(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address) != 0) {
        const int error = errno;
        ::close(fd);
        return ioError(what, error);
    }
    return fd;
}

dev::Result<int, HostError> adoptCanFd(int fd)
{
    const std::string what = "--can-fd " + std::to_string(fd);
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags < 0)
        return ioError(what, errno);
    int type = 0;
    socklen_t length = sizeof type;
    if (::getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0)
        return ioError(what + " is no socket", errno);
    if (type != SOCK_SEQPACKET && type != SOCK_DGRAM && type != SOCK_RAW)
        return HostError{cli::kExitConnection,
                         what + ": a stream socket does not keep can_frame boundaries "
                                "(use SOCK_SEQPACKET or a CAN_RAW socket)"};
    if (::fcntl(fd, F_SETFL, flags | O_NONBLOCK) != 0 || ::fcntl(fd, F_SETFD, FD_CLOEXEC) != 0)
        return ioError(what, errno);
    return fd;
}

std::string candumpText(std::span<const std::uint8_t> images)
{
    static const char kDigits[] = "0123456789ABCDEF";
    std::string out;
    for (std::size_t at = 0; at < images.size(); at += dev::canopen::kSocketCanFrameSize) {
        const auto image =
            images.subspan(at, std::min(dev::canopen::kSocketCanFrameSize, images.size() - at));
        out += out.empty() ? "" : " ";
        const auto frame = dev::canopen::fromSocketCan(image);
        if (frame.ok()) {
            out += dev::canopen::formatCandump(*frame);
            continue;
        }
        out += '[';
        for (std::size_t i = 0; i < image.size(); ++i) {
            out += i == 0 ? "" : " ";
            out += kDigits[image[i] >> 4];
            out += kDigits[image[i] & 0x0F];
        }
        out += ']';
    }
    return out;
}

} // namespace vt::simapp
