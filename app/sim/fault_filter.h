// FaultFilter: the --fault schedule of valvetune-sim applied to the device's answers: drop,
// corrupt one byte, hold back by a delay (order kept), and end the connection after N answers.
// Same draws as transports/fault_link (four std::mt19937 draws per answer, whatever happens to
// it), so one seed gives one schedule. Owner: SimHost, one per line or TCP connection;
// single-threaded.
#pragma once

#include "transports/fault_spec.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <vector>

namespace vt::simapp {

class FaultFilter
{
public:
    using Bytes = std::vector<std::uint8_t>;

    struct Answer
    {
        Bytes bytes;
        bool corrupted = false;
        bool delayed = false;
    };
    enum class Verdict { Passed, Dropped, AfterCut };

    FaultFilter(const link::FaultRates &rates, std::optional<std::uint64_t> cutAfter,
                std::uint32_t seed);

    // One answer the device produced at nowUs. Passed: released() hands it out (at once, or
    // after the delay); Dropped: it vanished; AfterCut: the cut count was already reached.
    Verdict push(Bytes answer, std::int64_t nowUs);
    // Answers whose time has come, in order.
    std::vector<Answer> release(std::int64_t nowUs);
    // The cut count is reached and every answer before it has been released: close now.
    bool cutDue() const { return m_cutAfter && m_answers >= *m_cutAfter && m_held.empty(); }
    // When the next held answer is due; nullopt when none is held.
    std::optional<std::int64_t> nextDueUs() const;

    std::uint64_t answers() const { return m_answers; }
    bool isNull() const { return m_rates.isNull() && !m_cutAfter; }

private:
    struct Held
    {
        Answer answer;
        std::int64_t dueUs = 0;
    };

    link::FaultRates m_rates;
    std::optional<std::uint64_t> m_cutAfter;
    std::mt19937 m_rng;
    std::deque<Held> m_held;
    std::uint64_t m_answers = 0;
};

} // namespace vt::simapp
