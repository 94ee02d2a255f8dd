// What the TEST-ONLY tty shim (ioctl_shim.cpp) saw: the last termios libserialport asked a
// pseudo-terminal for. A pty cannot store parity or a character size other than 8 (the kernel's
// pty driver forces CS8 and clears PARENB), so tests check those bits in the request — exactly
// what a real UART driver would receive — and read everything else back from the pty itself.
#pragma once

#include <sys/types.h>
#include <termios.h>

namespace vt::test {

// The last tcsetattr() request for the tty device `device` (st_rdev of the slave), if any.
bool lastTermiosRequest(dev_t device, termios *out);

} // namespace vt::test
