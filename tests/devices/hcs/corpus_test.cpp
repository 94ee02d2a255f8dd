// Seeds of fuzz_hcs_telegram (tests/fuzz/hcs/hcs_telegram_fuzz.cpp): one selector byte (bit 0
// OPAT, bit 1 response) followed by a worked example.
#include "seed_corpus.h"
#include "worked_examples.h"

using namespace vt::test::hcs_examples;

TEST(HcsCorpus, SeedsAreTheWorkedExamples)
{
    for (const Example &ex : allExamples()) {
        vt::dev::Bytes seed;
        seed.push_back(static_cast<std::uint8_t>((ex.family == Family::Opat ? 1 : 0) |
                                                 (ex.direction == Direction::Response ? 2 : 0)));
        seed.insert(seed.end(), ex.bytes.begin(), ex.bytes.end());
        vt::test::checkOrWriteSeed("fuzz_hcs_telegram", ex.name, seed);
    }
}
