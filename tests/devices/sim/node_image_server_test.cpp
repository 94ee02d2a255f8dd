// The node image front end: fixed-length process images as a PLC exchanges them cyclically
// (ARCHITECTURE.md "node image"; DMA Profinet manual §4.5.4 "IN/OUT 42 byte"), answered only on
// change (§1.4), multiplexed for CMD 15, exception 9 for a CMD 15 telegram longer than the image
// (DMA Profibus Anleitung §5.1 "CMD15 2fold 9B-I 13B-O").
#include "../hcs/worked_examples.h"
#include "hcs/telegram.h"
#include "sim/hcs_codes.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::test::hcs_examples;

namespace {

Bytes withTadr(Bytes telegram, std::uint8_t tadr)
{
    telegram.at(0) = tadr;
    return telegram;
}

Bytes image(const Bytes &telegram, std::size_t size)
{
    Bytes out = telegram;
    out.resize(size, 0);
    return out;
}

} // namespace

TEST(NodeImageServer, CyclicImagesAnsweredOnChangeOnly)
{
    SimClock clock;
    auto n = std::move(makeNode(clock, "dma-pn-v13", 3)).value();
    NodeImageServer server(clock, *n);
    ASSERT_EQ(server.layout().outputBytes, 42u);
    const Bytes first = image(kDma442Request, 42);
    // The PLC sends its image every cycle; split across reads as TCP may deliver it.
    server.receive(std::span<const std::uint8_t>(first).first(20));
    EXPECT_TRUE(server.drain().empty());
    server.receive(std::span<const std::uint8_t>(first).subspan(20));
    Bytes a = server.drain();
    ASSERT_EQ(a.size(), 42u);
    EXPECT_EQ(a[0], 0x23);
    EXPECT_EQ(a[1], 1);
    EXPECT_TRUE(std::all_of(a.begin() + 9, a.end(), [](std::uint8_t b) { return b == 0; }));
    for (int cycle = 0; cycle < 3; ++cycle) // unchanged image: no answer
        server.receive(first);
    EXPECT_TRUE(server.drain().empty());
    server.receive(image(withTadr(kDma442Request, 0x24), 42));
    a = server.drain();
    ASSERT_EQ(a.size(), 42u);
    EXPECT_EQ(a[1], 2);
    EXPECT_EQ(server.imagesReceived(), 5u);
    EXPECT_EQ(server.imagesAnswered(), 2u);
    // Reconnect: the same image is answered again.
    server.reset();
    server.receive(image(withTadr(kDma442Request, 0x24), 42));
    EXPECT_EQ(server.drain().size(), 42u);
}

TEST(NodeImageServer, Cmd15LongerThanTheImageGetsException9)
{
    SimClock clock;
    auto n = std::move(makeNode(clock, "dma-pb-v15", 3)).value();
    NodeImageServer server(clock, *n, NodeImageLayout{13, 9}); // "CMD15 2fold 9B-I 13B-O"
    Bytes q = hcs::encode(hcs::CyclicRequest{0x23, {{}, {}, {}}}, hcs::Family::Dma).value();
    q.resize(13);
    server.receive(q);
    EXPECT_EQ(server.drain(), (Bytes{0x23, 0x00, 0x8F, exce::kBufferTooSmall, 0, 0, 0, 0, 0}));
}

TEST(NodeImageServer, OpatImageCarriesCmd3And6)
{
    SimClock clock;
    auto n = std::move(makeNode(clock, "opat", 1)).value();
    NodeImageServer server(clock, *n);
    ASSERT_EQ(server.layout().outputBytes, 43u);
    server.receive(image(kOpat27Write, 43));
    EXPECT_EQ(server.drain(), image(kOpat27Write, 43));
    server.receive(image(kOpat27ReadRequest, 43));
    const Bytes a = server.drain();
    ASSERT_EQ(a.size(), 43u);
    EXPECT_EQ(Bytes(a.begin(), a.begin() + 4),
              Bytes(kOpat27ReadResponse.begin(), kOpat27ReadResponse.begin() + 4));
}
