// Seeds of the Modbus fuzzers (tests/fuzz/modbus/): one selector byte (bit 0 = response) and the
// frame; the de-framer seeds add a chunk-size byte and concatenate frames with noise between them.
#include "../hcs/seed_corpus.h"
#include "modbus_vectors.h"

using namespace vt::test::modbus_vectors;

namespace {

std::uint8_t selector(Direction d)
{
    return d == Direction::Response ? 1 : 0;
}

} // namespace

TEST(ModbusCorpus, SeedsAreTheTestVectors)
{
    for (const Vector &v : rtuVectors()) {
        Bytes seed{selector(v.direction)};
        seed.insert(seed.end(), v.bytes.begin(), v.bytes.end());
        vt::test::checkOrWriteSeed("fuzz_modbus_rtu", v.name, seed);
    }
    for (const Vector &v : tcpVectors()) {
        Bytes seed{selector(v.direction)};
        seed.insert(seed.end(), v.bytes.begin(), v.bytes.end());
        vt::test::checkOrWriteSeed("fuzz_modbus_tcp", v.name, seed);
    }
    // De-framer: byte 0 bit 0 = response, bit 1 = TCP; byte 1 = chunk-size seed; then the stream.
    Bytes rtu{1, 3};
    for (const Bytes &f : {kRtuReadD107Response, Bytes{0xFF, 0x00}, kRtuWriteC107, kRtuReadWrongId})
        rtu.insert(rtu.end(), f.begin(), f.end());
    vt::test::checkOrWriteSeed("fuzz_modbus_deframer", "rtu-responses-with-noise", rtu);
    Bytes rtuReq{0, 1};
    for (const Bytes &f : {kRtuReadD107, kSerialLineSpecRead, kRtuWriteMinus9999})
        rtuReq.insert(rtuReq.end(), f.begin(), f.end());
    vt::test::checkOrWriteSeed("fuzz_modbus_deframer", "rtu-requests", rtuReq);
    Bytes tcp{3, 5};
    for (const Bytes &f : {kTcpReadD107Response, kTcpWriteC107, kTcpReadWrongId})
        tcp.insert(tcp.end(), f.begin(), f.end());
    vt::test::checkOrWriteSeed("fuzz_modbus_deframer", "tcp-responses", tcp);
}
