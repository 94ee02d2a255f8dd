// What does bounds-checked reading (STYLE.md rule 6) cost? ByteReader against unchecked index
// arithmetic over the same CMD 15 responses (9 bytes: TADR SADR CMD STATUS VALUE1 VALUE2).
#include "core/byte_reader.h"

#include <benchmark/benchmark.h>
#include <cstdint>
#include <vector>

namespace {

std::vector<std::uint8_t> frames(std::size_t count)
{
    std::vector<std::uint8_t> out;
    out.reserve(count * 9);
    for (std::size_t i = 0; i < count; ++i) {
        const auto v = static_cast<std::uint8_t>(i);
        out.insert(out.end(), {v, 0x01, 0x0F, 0x40, 0x00, 0x03, 0xE8, v, 0x10});
    }
    return out;
}

void BM_UncheckedIndexBaseline(benchmark::State &state)
{
    const auto data = frames(1024);
    for (auto _ : state) {
        std::int64_t sum = 0;
        for (std::size_t p = 0; p + 9 <= data.size(); p += 9) {
            sum += data[p] + data[p + 1] + data[p + 2];
            sum += static_cast<std::int16_t>(data[p + 3] << 8 | data[p + 4]);
            sum += static_cast<std::int16_t>(data[p + 5] << 8 | data[p + 6]);
            sum += static_cast<std::int16_t>(data[p + 7] << 8 | data[p + 8]);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(data.size()));
}
BENCHMARK(BM_UncheckedIndexBaseline);

void BM_ByteReader(benchmark::State &state)
{
    const auto data = frames(1024);
    for (auto _ : state) {
        std::int64_t sum = 0;
        vt::dev::ByteReader r(data);
        while (r.remaining() >= 9) {
            sum += r.u8() + r.u8() + r.u8();
            sum += r.i16be();
            sum += r.i16be();
            sum += r.i16be();
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(data.size()));
}
BENCHMARK(BM_ByteReader);

} // namespace
