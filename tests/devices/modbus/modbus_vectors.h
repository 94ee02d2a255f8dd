// Modbus test vectors: the public reference frames (CRC check value, the classic "01 03 00 00 00 0A
// C5 CD", Modbus over Serial Line's "11 03 00 6B 00 03 76 87") and the HCS worked examples mapped
// to Modbus as ARCHITECTURE.md decides (CMD 3 = FC 3, CMD 6 = FC 6, register = parameter ID).
// CRCs were cross-checked against libmodbus (libmodbus_test.cpp).
#pragma once

#include "core/byte_writer.h"
#include "core/direction.h"

#include <string>
#include <vector>

namespace vt::test::modbus_vectors {

using vt::dev::Bytes;
using vt::dev::Direction;

inline const Bytes kClassicRead10{0x01, 0x03, 0x00, 0x00, 0x00, 0x0A, 0xC5, 0xCD};
inline const Bytes kSerialLineSpecRead{0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87};
// DMA Profinet manual §3.7 as Modbus RTU, unit 1: read d1.07 (ID 0x0007), answer 0x0133.
inline const Bytes kRtuReadD107{0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x35, 0xCB};
inline const Bytes kRtuReadD107Response{0x01, 0x03, 0x02, 0x01, 0x33, 0xF9, 0xC1};
// DMA Profinet manual §3.7: write C1.07 (ID 0x0030) = 1000; FC 6 echoes the request.
inline const Bytes kRtuWriteC107{0x01, 0x06, 0x00, 0x30, 0x03, 0xE8, 0x89, 0x7B};
// DMA Profinet manual §3.8: set value -9.999 V (0xD8F1) to ID 0x0027.
inline const Bytes kRtuWriteMinus9999{0x01, 0x06, 0x00, 0x27, 0xD8, 0xF1, 0xA2, 0x45};
// Exceptions carrying HCS EXCE codes: FC 3 code 2 = wrong ID, FC 6 code 3 = wrong data value.
inline const Bytes kRtuReadWrongId{0x01, 0x83, 0x02, 0xC0, 0xF1};
inline const Bytes kRtuWriteWrongData{0x01, 0x86, 0x03, 0x02, 0x61};
// ARCHITECTURE.md "Monitor": the d-block 0x07..0x0D in one request (7 registers).
inline const Bytes kRtuReadDBlock{0x01, 0x03, 0x00, 0x07, 0x00, 0x07, 0xB5, 0xC9};
// Modbus TCP, transaction 1, unit 1: the same read and its answer.
inline const Bytes kTcpReadD107{0x00, 0x01, 0x00, 0x00, 0x00, 0x06,
                                0x01, 0x03, 0x00, 0x07, 0x00, 0x01};
inline const Bytes kTcpReadD107Response{0x00, 0x01, 0x00, 0x00, 0x00, 0x05,
                                        0x01, 0x03, 0x02, 0x01, 0x33};
inline const Bytes kTcpWriteC107{0x00, 0x02, 0x00, 0x00, 0x00, 0x06,
                                 0x01, 0x06, 0x00, 0x30, 0x03, 0xE8};
inline const Bytes kTcpReadWrongId{0x00, 0x03, 0x00, 0x00, 0x00, 0x03, 0x01, 0x83, 0x02};

struct Vector
{
    std::string name;
    Direction direction;
    Bytes bytes;
};

inline std::vector<Vector> rtuVectors()
{
    const auto Q = Direction::Request;
    const auto A = Direction::Response;
    return {
        {"classic-read10", Q, kClassicRead10},
        {"serial-line-spec-read", Q, kSerialLineSpecRead},
        {"read-d107", Q, kRtuReadD107},
        {"read-d107-response", A, kRtuReadD107Response},
        {"write-c107", Q, kRtuWriteC107},
        {"write-c107-response", A, kRtuWriteC107},
        {"write-minus9999", Q, kRtuWriteMinus9999},
        {"read-wrong-id", A, kRtuReadWrongId},
        {"write-wrong-data", A, kRtuWriteWrongData},
        {"read-d-block", Q, kRtuReadDBlock},
    };
}

inline std::vector<Vector> tcpVectors()
{
    return {
        {"read-d107", Direction::Request, kTcpReadD107},
        {"read-d107-response", Direction::Response, kTcpReadD107Response},
        {"write-c107", Direction::Request, kTcpWriteC107},
        {"write-c107-response", Direction::Response, kTcpWriteC107},
        {"read-wrong-id", Direction::Response, kTcpReadWrongId},
    };
}

} // namespace vt::test::modbus_vectors
