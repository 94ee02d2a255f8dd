// The streaming HART de-framer (HART-7 manual §2.3: preambles synchronise, byte count sizes, XOR
// checksum closes) against split reads, several frames per read, noise and corrupted frames.
#include "hart/deframer.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hart;

namespace {

Bytes frameBytes(std::uint8_t command, Bytes data, bool response = false)
{
    const Address a = longAddress(0xE3F0, 0x123456);
    Frame f = response ? makeResponse(a, command, 0, 0, std::move(data))
                       : makeRequest(a, command, std::move(data));
    return *encodeFrame(f);
}

std::vector<DeframerEvent> feedAll(Deframer &d, const Bytes &bytes, std::size_t chunk)
{
    std::vector<DeframerEvent> all;
    for (std::size_t i = 0; i < bytes.size(); i += chunk) {
        const auto part =
            std::span<const std::uint8_t>(bytes).subspan(i, std::min(chunk, bytes.size() - i));
        auto events = d.feed(part);
        all.insert(all.end(), events.begin(), events.end());
    }
    return all;
}

std::size_t countFrames(const std::vector<DeframerEvent> &events)
{
    return static_cast<std::size_t>(
        std::count_if(events.begin(), events.end(),
                      [](const DeframerEvent &e) { return e.kind == DeframerEvent::Kind::Frame; }));
}

} // namespace

TEST(HartDeframer, Section23SplitAcrossReadsInEveryChunkSize)
{
    const Bytes wire = frameBytes(131, {0xFA, 0x06, 0x00, 0x01, 0xC2});
    for (std::size_t chunk = 1; chunk <= wire.size(); ++chunk) {
        Deframer d;
        const auto events = feedAll(d, wire, chunk);
        ASSERT_EQ(events.size(), 1u) << "chunk " << chunk;
        EXPECT_EQ(events[0].kind, DeframerEvent::Kind::Frame);
        EXPECT_EQ(events[0].frame.command, 131);
        EXPECT_EQ(events[0].raw, wire);
        EXPECT_FALSE(d.midFrame());
    }
}

TEST(HartDeframer, SeveralFramesInOneReadWithNoiseBetween)
{
    Bytes stream{0x12, 0x34, 0xFF, 0x00}; // noise, a lone preamble included
    const Bytes a = frameBytes(0, {});
    const Bytes b = frameBytes(132, {0xEE, 0x08, 0x00, 0x00, 0x00, 0x00, 0x50}, true);
    stream.insert(stream.end(), a.begin(), a.end());
    stream.insert(stream.end(), {0x55, 0xAA});
    stream.insert(stream.end(), b.begin(), b.end());
    Deframer d;
    const auto events = d.feed(stream);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].frame.command, 0);
    EXPECT_EQ(events[1].frame.command, 132);
    EXPECT_TRUE(events[1].frame.isResponse());
    EXPECT_EQ(d.discardedBytes(), 6u);
}

TEST(HartDeframer, BadChecksumGivesErrorAndResyncs)
{
    Bytes broken = frameBytes(131, {0xFA, 0x06, 0x00, 0x01, 0xC2});
    broken.back() ^= 0x5A;
    const Bytes good = frameBytes(130, {0xFA, 0x06, 0x00});
    Bytes stream = broken;
    stream.insert(stream.end(), good.begin(), good.end());
    Deframer d;
    const auto events = feedAll(d, stream, 3);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, DeframerEvent::Kind::Error);
    EXPECT_EQ(events[0].error.code, DecodeErrc::BadChecksum);
    EXPECT_EQ(events[0].raw, broken);
    EXPECT_EQ(events[1].frame.command, 130);
}

TEST(HartDeframer, FrameHiddenInsideAFalseStartIsFound)
{
    // A false delimiter announces 255 bytes and swallows the real frame; the checksum fails and
    // the bytes after the false delimiter are scanned again.
    Bytes stream{0xFF, 0xFF, 0x02, 0x80, 0x00, 0xFF};
    const Bytes real = frameBytes(1, {});
    stream.insert(stream.end(), real.begin(), real.end());
    stream.resize(stream.size() + 300, 0x00);
    Deframer d;
    const auto events = feedAll(d, stream, 7);
    ASSERT_GE(events.size(), 2u);
    EXPECT_EQ(events[0].error.code, DecodeErrc::BadChecksum);
    EXPECT_EQ(countFrames(events), 1u);
    EXPECT_EQ(
        std::find_if(events.begin(), events.end(),
                     [](const DeframerEvent &e) { return e.kind == DeframerEvent::Kind::Frame; })
            ->frame.command,
        1);
}

TEST(HartDeframer, InvalidDelimiterAfterPreamblesIsReported)
{
    Deframer d;
    const auto events = d.feed(Bytes{0xFF, 0xFF, 0xFF, 0x07});
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].error.code, DecodeErrc::BadValue);
    EXPECT_FALSE(d.midFrame());
}

TEST(HartDeframer, FlushReportsAnIncompleteFrameAndFindsFramesInIt)
{
    Bytes stream = frameBytes(131, {0xFA, 0x06, 0x00, 0x01, 0xC2});
    stream.resize(stream.size() - 2); // cut off
    Deframer d;
    EXPECT_TRUE(d.feed(stream).empty());
    EXPECT_TRUE(d.midFrame());
    const auto events = d.flush();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].error.code, DecodeErrc::Truncated);
    EXPECT_FALSE(d.midFrame());
    // After the gap the next frame is found normally.
    const auto next = d.feed(frameBytes(0, {}));
    ASSERT_EQ(next.size(), 1u);
    EXPECT_EQ(next[0].kind, DeframerEvent::Kind::Frame);
}

TEST(HartDeframer, PreambleCountIsBoundedAndMinimumApplies)
{
    Bytes stream(10000, 0xFF);
    const Bytes f = frameBytes(0, {});
    stream.insert(stream.end(), f.begin() + 5, f.end()); // delimiter … without its own preambles
    Deframer d;
    const auto events = d.feed(stream);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].frame.preambles, kMaxPreambles);
    EXPECT_EQ(events[0].raw.size(), kMaxPreambles + f.size() - 5);

    Deframer strict(Deframer::Options{5});
    Bytes few{0xFF, 0xFF, 0xFF};
    few.insert(few.end(), f.begin() + 5, f.end());
    EXPECT_TRUE(strict.feed(few).empty());
    EXPECT_EQ(strict.feed(f).size(), 1u);
}

TEST(HartDeframer, ResponseWithByteCountBelowTwoIsAnError)
{
    Bytes bad{0xFF, 0xFF, 0x06, 0x80, 0x00, 0x01, 0x00};
    std::uint8_t x = 0;
    for (std::size_t i = 2; i < bad.size(); ++i)
        x ^= bad[i];
    bad.push_back(x);
    Deframer d;
    const auto events = d.feed(bad);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].error.code, DecodeErrc::BadLength);
}
