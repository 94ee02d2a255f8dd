// Shared helpers of the protocol adapter tests: one adapter wired to one simulator front end
// (a ByteServer) the way the session uses it — encode, send, feed the answer in chunks until a
// reply that is not Mismatch, else "time out": resetFraming() and retry with a fresh encode().
// No sleeps: simulated time only moves when a test says so.
#pragma once

#include "access/transaction.h"
#include "core/byte_server.h"
#include "sim/sim_clock.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::access::test {

inline constexpr std::size_t kWhole = static_cast<std::size_t>(-1);

// Feeds `bytes` in chunks of `chunk` bytes; the first reply that is not Mismatch, else the last
// Mismatch, else nullopt.
inline std::optional<Reply> feedChunks(ProtocolAdapter &adapter,
                                       std::span<const std::uint8_t> bytes, const Transaction &t,
                                       std::size_t chunk = kWhole)
{
    std::optional<Reply> last;
    std::size_t at = 0;
    while (at < bytes.size()) {
        const std::size_t n = std::min(chunk, bytes.size() - at);
        auto reply = adapter.feed(bytes.subspan(at, n), t);
        at += n;
        if (reply && reply->status != ReplyStatus::Mismatch)
            return reply;
        if (reply)
            last = std::move(reply);
    }
    return last;
}

struct Rig
{
    ProtocolAdapter &adapter;
    ByteServer &server;
    sim::SimClock &clock;
    std::size_t chunk = kWhole; // how the link hands the answer over

    // The server's answer to `request`: what it has at once, else after up to 100 ms simulated
    // time (a delayed EEPROM write), in 1 ms steps.
    Bytes ask(std::span<const std::uint8_t> request)
    {
        server.receive(request);
        Bytes answer = server.drain();
        for (int ms = 0; answer.empty() && ms < 100; ++ms) {
            clock.advance(1000);
            answer = server.drain();
        }
        return answer;
    }

    // One transaction as the session runs it, up to `attempts` attempts.
    std::optional<Reply> run(const Transaction &t, int attempts = 2)
    {
        for (int attempt = 0; attempt < attempts; ++attempt) {
            const Bytes request = adapter.encode(t);
            if (request.empty()) {
                ADD_FAILURE() << "encode() gave no bytes";
                return std::nullopt;
            }
            const Bytes answer = ask(request);
            auto reply = feedChunks(adapter, answer, t, chunk);
            if (reply && reply->status != ReplyStatus::Mismatch)
                return reply;
            adapter.resetFraming(); // the session's timeout
        }
        return std::nullopt;
    }

    // Runs every transaction of a read plan; the value read for each row (in plan order).
    std::vector<std::pair<const ParamMeta *, RawValue>>
    readAll(const std::vector<Transaction> &plan)
    {
        std::vector<std::pair<const ParamMeta *, RawValue>> out;
        for (const Transaction &t : plan) {
            auto reply = run(t);
            if (!reply || reply->status != ReplyStatus::Ok ||
                reply->values.size() != t.rows.size()) {
                ADD_FAILURE() << "read of "
                              << (t.rows.empty() ? std::string("?") : t.rows.front()->name)
                              << " failed"
                              << (reply ? ": " + reply->exceptionText.en
                                        : std::string(" (no answer)"));
                continue;
            }
            for (std::size_t i = 0; i < t.rows.size(); ++i)
                out.emplace_back(t.rows[i], reply->values[i]);
        }
        return out;
    }
};

inline std::optional<Reply> okReply(std::optional<Reply> reply)
{
    EXPECT_TRUE(reply.has_value());
    if (reply) {
        EXPECT_EQ(reply->status, ReplyStatus::Ok) << reply->exceptionText.en;
    }
    return reply;
}

// Every byte of `answer` flipped in turn (XOR `mask`): the adapter never accepts a changed
// answer with other values than the true ones, and never accepts it at all at the positions
// `protectedAt` says are covered (header, addresses, checksum). Positions `valueAt` says are
// unprotected value bytes (no checksum in the telegram: TCP or the CAN controller checks) are
// skipped. After each try the session's timeout (resetFraming) follows and the unchanged answer
// is accepted again.
inline void expectCorruptionRejected(ProtocolAdapter &adapter, const Bytes &answer,
                                     const Transaction &t, const std::vector<RawValue> &truth,
                                     const std::function<bool(std::size_t)> &protectedAt,
                                     const std::function<bool(std::size_t)> &valueAt = {},
                                     std::uint8_t mask = 0x01)
{
    for (std::size_t i = 0; i < answer.size(); ++i) {
        if (valueAt && valueAt(i))
            continue;
        Bytes bad = answer;
        bad[i] = static_cast<std::uint8_t>(bad[i] ^ mask);
        adapter.resetFraming();
        const auto reply = adapter.feed(bad, t);
        if (reply && reply->status == ReplyStatus::Ok) {
            EXPECT_FALSE(protectedAt(i)) << "byte " << i << " changed, answer still accepted";
            EXPECT_EQ(reply->values, truth) << "byte " << i << " changed, wrong values accepted";
        }
        adapter.resetFraming();
        const auto again = adapter.feed(answer, t);
        ASSERT_TRUE(again.has_value());
        EXPECT_EQ(again->status, ReplyStatus::Ok) << "byte " << i;
    }
}

} // namespace vt::dev::access::test
