// OPAT manual §5.6 worked example (PROFIdrive axis for the master + CMD 15 for master and slave).
// The OCR damaged the hex column of the dumps; the bytes are rebuilt from the decimal and binary
// columns: "FF 0111… 127" = 0x7F, "84 100110 . 154" = 0x9A, "14 00011mo . 26" = 0x1A,
// "20 0o;onmot - 45" = 0x2D; the lost line 3 of the send telegram is 0x07 ("Set-value = 0x0700");
// the lost line 8 of both CMD 15 answers is 0x04 (binary/decimal ". 4"; HW_ENABLE as in the table).
#pragma once

#include "core/byte_writer.h"

namespace vt::test::profidrive_examples {

using vt::dev::Bytes;

// Send telegram: STW1 0x047F, NSOLL_A 0x0700 (== 1,093 V) | TADR 18, SNUM 1, CMD 15,
// master 0x00 0x1800 0x0000, slave 0x00 0x1800 0x0000 (0x1800 == "6,143V").
inline const Bytes kSec56Request{0x04, 0x7F, 0x07, 0x00, 0x12, 0x01, 0x0F, 0x00, 0x18,
                                 0x00, 0x00, 0x00, 0x00, 0x18, 0x00, 0x00, 0x00};
// Response from the PROFIdrive axis and the OPAT master (module 0).
inline const Bytes kSec56ResponseMaster{0x42, 0x37, 0xF3, 0x9A, 0x12, 0x00, 0x0F,
                                        0x04, 0x00, 0xFC, 0x1A, 0x0E, 0xA6};
// TADR changed to 19: the OPAT slave (module 1) answers the CMD 15 part.
inline const Bytes kSec56ResponseSlave{0x42, 0x37, 0xF9, 0x9A, 0x13, 0x01, 0x0F,
                                       0x04, 0x04, 0x02, 0x2D, 0x18, 0x00};
// Cable fracture at feedback 1 of the master, TADR 20: ZSW1 bit 3, NIST_A = error 2; status 0x0C02.
inline const Bytes kSec56ResponseCableFracture{0x40, 0x3F, 0x00, 0x02, 0x14, 0x00, 0x0F,
                                               0x0C, 0x02, 0x00, 0x00, 0x00, 0x00};

} // namespace vt::test::profidrive_examples
