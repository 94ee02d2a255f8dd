// Seeds of fuzz_profidrive (tests/fuzz/profidrive/): selector byte (bit 0 = response, bits 1-2 =
// layout: 0 auto, 1 telegram 1, 2 mixed) followed by the OPAT manual §5.6 images.
#include "../hcs/seed_corpus.h"
#include "worked_examples.h"

using namespace vt::test::profidrive_examples;

TEST(ProfidriveCorpus, SeedsAreTheSec5_6Example)
{
    struct Seed
    {
        const char *name;
        std::uint8_t selector;
        const Bytes &bytes;
    };
    const Bytes t1(kSec56Request.begin(), kSec56Request.begin() + 4);
    for (const Seed &s : {Seed{"sec5.6-request", 0, kSec56Request},
                          Seed{"sec5.6-response-master", 1, kSec56ResponseMaster},
                          Seed{"sec5.6-response-slave", 1, kSec56ResponseSlave},
                          Seed{"sec5.6-response-cable-fracture", 1, kSec56ResponseCableFracture},
                          Seed{"sec5.6-telegram1-only", 2, t1}}) {
        Bytes seed{s.selector};
        seed.insert(seed.end(), s.bytes.begin(), s.bytes.end());
        vt::test::checkOrWriteSeed("fuzz_profidrive", s.name, seed);
    }
}
