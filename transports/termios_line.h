// The termios of a raw serial line with the given settings, as the POSIX fallback of
// SerialWorker applies it: baud, character size, parity, stop bits, no flow control, no
// canonical processing, echo or CR/LF translation (a Modbus or HART frame is binary), VMIN 1 /
// VTIME 0 so a blocking reader waits for a byte instead of reading an empty line as end of file.
// Pure functions; any thread.
#pragma once

#include "transports/serial_settings.h"

#include <optional>
#include <termios.h>

namespace vt::link {

// The speed_t of a standard rate (50 … 4000000 on Linux), or nullopt.
std::optional<speed_t> termiosSpeed(int baudRate);
// The rate of a speed_t, or 0 for one this table does not know.
int termiosBaud(speed_t speed);

// Changes `t` to the raw line of `settings`; false (t untouched) for a rate termios lacks.
bool applyLineSettings(termios &t, const SerialSettings &settings);

// True when `held` is `wanted` except for the character size and the parity enable, the bits a
// pseudo-terminal cannot store (the kernel's pty driver forces CS8 without parity): such a
// device holds everything of the request it can.
bool differsOnlyInCharacterFormat(const termios &held, const termios &wanted);

} // namespace vt::link
