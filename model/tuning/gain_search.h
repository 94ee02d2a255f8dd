// GainSearch: the rule of the guided gain change (issue #18 §3) — from the overshoot measured at
// the current P gain (HCS C1.13 / C2.13, "100 == factor 1.00"), propose the next one toward the
// person's target: the highest P gain whose step overshoot stays within a limit (a stiffer P
// portion is a faster axis and more overshoot, docs/SIMULATOR-PLANT.md "What the tests
// measure"). Bounded: the gains stay within the row's range, at most `maxIterations` steps are
// measured, and the step size is a bracket search that always ends — double (or halve) until
// both a gain within the limit and one beyond it are known, then bisect between them. The I
// portion (C1.17) is kept as it is. Plain C++; any thread.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace vt::model {

// What the person asks for.
struct GainTarget
{
    enum class Kind {
        MaxOvershoot,            // overshoot ≤ maxOvershootPct, as close to it as the search gets
        FastestWithoutOvershoot, // the highest gain whose overshoot stays ≤ kNoOvershootPct
    };
    Kind kind = Kind::MaxOvershoot;
    double maxOvershootPct = 10;
};

// "Without overshoot" as the analysis can tell: noise of ±0.3 % of the step reads as up to
// 0.35 % of overshoot (docs/TUNING.md "Tolerances the tests hold"), so 1 % is none.
constexpr double kNoOvershootPct = 1.0;
// A MaxOvershoot search takes any gain whose overshoot is within this share of the limit below
// it (10 % allowed: 7 … 10 % ends the search).
constexpr double kAcceptShare = 0.3;
// The bracket is resolved when it is this narrow relative to its lower gain (or one raw step).
constexpr double kResolution = 0.05;

// The P gain and I portion, raw as the device holds them.
struct Gains
{
    double p = 0;
    double i = 0;
    bool operator==(const Gains &) const = default;
};

struct GainMeasurement
{
    Gains gains;
    double overshootPct = 0;
};

enum class GainVerdict {
    Measure,     // write `next` and measure again
    Reached,     // `best` meets the target: keep it
    Exhausted,   // the iterations ran out: `best` is the best gain within the limit (if any)
    Unreachable, // the limit is not met even at the lowest gain (or met at the highest: Reached)
};
std::string_view key(GainVerdict verdict);

struct GainProposal
{
    GainVerdict verdict = GainVerdict::Measure;
    Gains next;                // Measure: the gains to write
    std::optional<Gains> best; // the highest gain measured within the limit
};

class GainSearch
{
public:
    // `start`: the gains on the device; pMin/pMax: the P row's raw range.
    GainSearch(GainTarget target, Gains start, double pMin, double pMax, int maxIterations);

    // The overshoot limit the target stands for.
    double limitPct() const;
    // Records the overshoot measured at `gains` and says what to do next. An overshoot of
    // +infinity stands for a response that rang past the set value and did not settle within the
    // hold: beyond any limit.
    GainProposal measured(const Gains &gains, double overshootPct);
    const std::vector<GainMeasurement> &history() const { return m_history; }

private:
    bool accepted(double overshootPct) const;
    GainProposal propose(const Gains &at) const;

    GainTarget m_target;
    double m_pMin;
    double m_pMax;
    int m_maxIterations;
    double m_i;                            // the I portion, kept
    std::optional<GainMeasurement> m_low;  // highest gain within the limit
    std::optional<GainMeasurement> m_high; // lowest gain beyond the limit
    std::vector<GainMeasurement> m_history;
};

} // namespace vt::model
