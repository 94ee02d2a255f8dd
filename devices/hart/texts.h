// Texts for HART frames in both languages: command names, response codes, communication error
// and field-device status bits (HART-7 manual §4.4.1 "Status", §5.1), unit symbols.
#pragma once

#include "core/local_text.h"

#include <cstdint>
#include <string>

namespace vt::dev::hart {

LocalText commandText(std::uint8_t command);
// First status byte with bit 7 clear: command response code (HART-7 manual §4.4.1 lists 0, 5, 6;
// the others are the HART common response codes).
LocalText responseCodeText(std::uint8_t code);
// First status byte with bit 7 set: communication error bits 6..0.
LocalText commErrorBitText(int bit);
// Second status byte, bits 7..0 (HART-7 manual §4.4.1 "device status").
LocalText deviceStatusBitText(int bit);
// True when the first status byte reports an error (no usable data follows), false for success
// and warnings (HART common response codes 8 and 24..27/96..127 style warnings are not errors).
bool isErrorResponse(std::uint8_t responseCode);
// Short symbol for a HART engineering unit code ("mA"), empty when not in our small table.
std::string unitSymbol(std::uint8_t unit);

} // namespace vt::dev::hart
