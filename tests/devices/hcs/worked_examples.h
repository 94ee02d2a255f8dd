// The manuals' worked examples as byte vectors, shared by the HCS tests and the fuzz seed corpus.
// OCR repairs are noted where they were needed (see docs/protocol-notes/hcs-modbus-profidrive.md).
#pragma once

#include "core/byte_writer.h"
#include "core/direction.h"
#include "hcs/types.h"

#include <string>
#include <vector>

namespace vt::test::hcs_examples {

using vt::dev::Bytes;
using vt::dev::Direction;
using vt::dev::hcs::Family;

// ---- OPAT manual (Rev R2.1) ----
// §2.3 / §2.6: module 3 not installed, SADR 3.
inline const Bytes kOpat23ReadError{0x23, 0x03, 0x83, 0x05};
inline const Bytes kOpat26WriteError{0x23, 0x03, 0x86, 0x05};
// §2.7: write C1.07 (ID 0x0030) = 1000 to the OPAT master; the response echoes it ("O0xE8" = 0xE8).
inline const Bytes kOpat27Write{0x23, 0x00, 0x06, 0x00, 0x30, 0x03, 0xE8};
// §2.7: read d1.07 (ID 0x0007), N = 1.
inline const Bytes kOpat27ReadRequest{0x24, 0x00, 0x03, 0x00, 0x07, 0x00, 0x01};
// §2.7 response: the OCR prints CNT as 0x00; the text says "CNT = 2 (2 Bytes)" and the DMA manuals
// §3.7 print 0x02 — repaired to 0x02.
inline const Bytes kOpat27ReadResponse{0x24, 0x00, 0x03, 0x02, 0x01, 0x33};
// §2.8: set value via the bus, ID 0x0027: 0.000 V, 5.000 V, 9.999 V, -9.999 V.
inline const Bytes kOpat28Zero{0x12, 0x00, 0x06, 0x00, 0x27, 0x00, 0x00};
inline const Bytes kOpat28Five{0x12, 0x00, 0x06, 0x00, 0x27, 0x13, 0x88};
inline const Bytes kOpat28Max{0x12, 0x00, 0x06, 0x00, 0x27, 0x27, 0x0F};
inline const Bytes kOpat28Min{0x12, 0x00, 0x06, 0x00, 0x27, 0xD8, 0xF1};
// §3.3: CMD 15 error, SNUM 3 but module 3 not installed.
inline const Bytes kOpat33CyclicError{0x23, 0x03, 0x8F, 0x08};
// §3.4.1: master only (SNUM 0), 1.000 V to A1.01 ("O0xOF" = 0x0F).
inline const Bytes kOpat341Request{0x23, 0x00, 0x0F, 0x00, 0x03, 0xE8, 0x00, 0x00};
// §3.4.1 response: status 0x40 00, d1.11 = 1000, d1.10 = 0 (the OCR's ")" is "(0)").
inline const Bytes kOpat341Response{0x23, 0x00, 0x0F, 0x40, 0x00, 0x03, 0xE8, 0x00, 0x00};
// §3.4.2: master + 2 slaves (SNUM 2): 1.000 V, 2.000 V, -3.000 V.
inline const Bytes kOpat342Request{0x23, 0x02, 0x0F, 0x00, 0x03, 0xE8, 0x00, 0x00, 0x00,
                                   0x07, 0xD0, 0x00, 0x00, 0x00, 0xF4, 0x48, 0x00, 0x00};
inline const Bytes kOpat342ResponseMaster{0x23, 0x00, 0x0F, 0x40, 0x00, 0x03, 0xE8, 0x00, 0x00};
inline const Bytes kOpat342ResponseSlave1{0x24, 0x01, 0x0F, 0x40, 0x00, 0x07, 0xD0, 0x00, 0x00};
inline const Bytes kOpat342ResponseSlave2{0x25, 0x02, 0x0F, 0x40, 0x00, 0xF4, 0x48, 0x00, 0x00};
inline const Bytes kOpat342ResponseMasterAgain{0x26, 0x00, 0x0F, 0x40, 0x00,
                                               0x03, 0xE8, 0x00, 0x00};

// ---- DMA Profinet manual (Rev R1.2) = DMA Profibus Anleitung (Rev R3.1): identical bytes ----
// Profinet §3.3 / §3.6, Profibus §3.3 / §3.6.
inline const Bytes kDma33ReadError{0x23, 0x03, 0x83, 0x05};
inline const Bytes kDma36WriteError{0x23, 0x03, 0x86, 0x05};
// Profinet §3.7 / Profibus §3.7.
inline const Bytes kDma37Write{0x23, 0x01, 0x06, 0x00, 0x30, 0x03, 0xE8};
inline const Bytes kDma37ReadRequest{0x24, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01};
inline const Bytes kDma37ReadResponse{0x24, 0x01, 0x03, 0x02, 0x01, 0x33};
// Profinet §3.8 / Profibus §3.8.
inline const Bytes kDma38Zero{0x12, 0x01, 0x06, 0x00, 0x27, 0x00, 0x00};
inline const Bytes kDma38Five{0x12, 0x01, 0x06, 0x00, 0x27, 0x13, 0x88};
inline const Bytes kDma38Max{0x12, 0x01, 0x06, 0x00, 0x27, 0x27, 0x0F};
inline const Bytes kDma38Min{0x12, 0x01, 0x06, 0x00, 0x27, 0xD8, 0xF1};
// Profinet §4.3 / Profibus §4.3.
inline const Bytes kDma43CyclicError{0x23, 0x03, 0x8F, 0x08};
// Profinet §4.4.1 / Profibus §4.4.1 (V13 / V15): 1.000 V to module 1; it answers 0 mA / 270 mA.
inline const Bytes kDma441Request{0x23, 0x01, 0x0F, 0x00, 0x03, 0xE8, 0x00, 0x00};
inline const Bytes kDma441Response{0x23, 0x01, 0x0F, 0x40, 0x00, 0x00, 0x00, 0x01, 0x0E};
// Profinet §4.4.2 / Profibus §4.4.2: three modules, 1.000 / 2.000 / -3.000 V.
inline const Bytes kDma442Request{0x23, 0x03, 0x0F, 0x00, 0x03, 0xE8, 0x00, 0x00, 0x00,
                                  0x07, 0xD0, 0x00, 0x00, 0x00, 0xF4, 0x48, 0x00, 0x00};
inline const Bytes kDma442Response1{0x23, 0x01, 0x0F, 0x40, 0x00, 0x00, 0x00, 0x01, 0x0E};
inline const Bytes kDma442Response2{0x24, 0x02, 0x0F, 0x40, 0x00, 0x00, 0x00, 0x02, 0x1C};
inline const Bytes kDma442Response3{0x25, 0x03, 0x0F, 0x40, 0x00, 0x03, 0x2A, 0x00, 0x00};
inline const Bytes kDma442Response1Again{0x26, 0x01, 0x0F, 0x40, 0x00, 0x00, 0x00, 0x01, 0x0E};

struct Example
{
    std::string name; // file name of the seed: "opat-2.7-write"
    Family family;
    Direction direction;
    Bytes bytes;
};

inline std::vector<Example> allExamples()
{
    const auto Q = Direction::Request;
    const auto A = Direction::Response;
    const auto O = Family::Opat;
    const auto D = Family::Dma;
    return {
        {"opat-2.3-read-error", O, A, kOpat23ReadError},
        {"opat-2.6-write-error", O, A, kOpat26WriteError},
        {"opat-2.7-write-request", O, Q, kOpat27Write},
        {"opat-2.7-write-response", O, A, kOpat27Write},
        {"opat-2.7-read-request", O, Q, kOpat27ReadRequest},
        {"opat-2.7-read-response", O, A, kOpat27ReadResponse},
        {"opat-2.8-zero", O, Q, kOpat28Zero},
        {"opat-2.8-five", O, Q, kOpat28Five},
        {"opat-2.8-max", O, Q, kOpat28Max},
        {"opat-2.8-min", O, Q, kOpat28Min},
        {"opat-3.3-cyclic-error", O, A, kOpat33CyclicError},
        {"opat-3.4.1-request", O, Q, kOpat341Request},
        {"opat-3.4.1-response", O, A, kOpat341Response},
        {"opat-3.4.2-request", O, Q, kOpat342Request},
        {"opat-3.4.2-response-master", O, A, kOpat342ResponseMaster},
        {"opat-3.4.2-response-slave1", O, A, kOpat342ResponseSlave1},
        {"opat-3.4.2-response-slave2", O, A, kOpat342ResponseSlave2},
        {"dma-3.3-read-error", D, A, kDma33ReadError},
        {"dma-3.6-write-error", D, A, kDma36WriteError},
        {"dma-3.7-write-request", D, Q, kDma37Write},
        {"dma-3.7-write-response", D, A, kDma37Write},
        {"dma-3.7-read-request", D, Q, kDma37ReadRequest},
        {"dma-3.7-read-response", D, A, kDma37ReadResponse},
        {"dma-3.8-five", D, Q, kDma38Five},
        {"dma-3.8-min", D, Q, kDma38Min},
        {"dma-4.3-cyclic-error", D, A, kDma43CyclicError},
        {"dma-4.4.1-request", D, Q, kDma441Request},
        {"dma-4.4.1-response", D, A, kDma441Response},
        {"dma-4.4.2-request", D, Q, kDma442Request},
        {"dma-4.4.2-response2", D, A, kDma442Response2},
        {"dma-4.4.2-response3", D, A, kDma442Response3},
    };
}

} // namespace vt::test::hcs_examples
