#include "step_metrics.h"

#include "core/vt_assert.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace vt::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kFinalShare = 0.1;  // the final-value window: the last 10 % of a hold
constexpr double kDeadLevel = 0.02;  // s(t) that ends the dead time
constexpr double kDriftLimit = 0.02; // allowed drift in the final-value window, of the step

std::size_t indexFrom(const std::vector<double> &t, double time)
{
    return static_cast<std::size_t>(
        std::distance(t.begin(), std::lower_bound(t.begin(), t.end(), time)));
}

// Time at which a straight line from (t0, s0) to (t1, s1) reaches `level`.
double crossingTime(double t0, double s0, double t1, double s1, double level)
{
    const double ds = s1 - s0;
    if (!(t1 > t0) || ds == 0)
        return t1;
    return t0 + std::clamp((level - s0) / ds, 0.0, 1.0) * (t1 - t0);
}

// The change across a window of `length` s that the least-squares line through samples
// [begin, end) shows: a trend shows in it, noise averages out of it.
double driftAcross(const Samples &a, std::size_t begin, std::size_t end, double length)
{
    const double n = static_cast<double>(end - begin);
    const double t0 = a.t[begin]; // centring keeps the sums small
    double st = 0, sy = 0;
    for (std::size_t i = begin; i < end; ++i) {
        st += a.t[i] - t0;
        sy += a.y[i];
    }
    const double mt = st / n, my = sy / n;
    double stt = 0, sty = 0;
    for (std::size_t i = begin; i < end; ++i) {
        const double dt = a.t[i] - t0 - mt;
        stt += dt * dt;
        sty += dt * (a.y[i] - my);
    }
    return stt > 0 ? sty / stt * length : 0.0;
}

// The normalised response of one hold: a leading point at the step time (the last sample before
// it, held), then every sample in (step, last].
class Response
{
public:
    Response(const Samples &actual, double stepTime, double start, double span, std::size_t first,
             std::size_t last)
        : m_a(actual), m_stepTime(stepTime), m_start(start), m_span(span), m_first(first),
          m_last(last)
    {
    }

    double firstReaching(double level) const
    {
        double prevT = m_stepTime;
        double prevS = s(m_first - 1);
        if (prevS >= level)
            return m_stepTime;
        for (std::size_t i = m_first; i <= m_last; ++i) {
            const double si = s(i);
            if (si >= level)
                return crossingTime(prevT, prevS, m_a.t[i], si, level);
            prevT = m_a.t[i];
            prevS = si;
        }
        return kNaN;
    }

    std::size_t peakIndex() const
    {
        std::size_t best = m_first;
        for (std::size_t i = m_first + 1; i <= m_last; ++i)
            if (s(i) > s(best))
                best = i;
        return best;
    }

    // Absolute time from which |s − 1| ≤ band until the last sample; NaN if the last is outside.
    double settledFrom(double band) const
    {
        const auto outside = [&](double si) { return std::abs(si - 1.0) > band; };
        if (outside(s(m_last)))
            return kNaN;
        std::size_t i = m_last;
        while (i >= m_first && !outside(s(i)))
            --i;
        // i is the last point outside the band (m_first − 1 stands for the leading point).
        const double ti = i >= m_first ? m_a.t[i] : m_stepTime;
        const double si = s(i);
        const double level = si > 1.0 ? 1.0 + band : 1.0 - band;
        return crossingTime(ti, si, m_a.t[i + 1], s(i + 1), level);
    }

    double s(std::size_t i) const { return (m_a.y[i] - m_start) / m_span; }

private:
    const Samples &m_a;
    double m_stepTime, m_start, m_span;
    std::size_t m_first, m_last; // samples after the step; m_first ≥ 1
};

} // namespace

std::vector<StepEdge> findStepEdges(const Samples &setValue, double minJump, double recordingEnd)
{
    std::vector<StepEdge> edges;
    VT_ASSERT(setValue.t.size() == setValue.y.size(), return edges);
    if (setValue.t.empty())
        return edges;
    double previous = setValue.t.front();
    for (std::size_t i = 1; i < setValue.t.size(); ++i) {
        const double from = setValue.y[i - 1];
        const double to = setValue.y[i];
        if (!(std::abs(to - from) > minJump))
            continue;
        if (!edges.empty())
            edges.back().end = setValue.t[i];
        edges.push_back({setValue.t[i], from, to, 0, setValue.t[i] - previous});
        previous = setValue.t[i];
    }
    if (!edges.empty())
        edges.back().end = std::max(recordingEnd, edges.back().time);
    return edges;
}

dev::Result<StepMetrics, StepProblem> stepMetrics(const Samples &actual, const StepEdge &edge)
{
    VT_ASSERT(actual.t.size() == actual.y.size(), return StepProblem::TooFewSamples);
    if (!(std::abs(edge.to - edge.from) > 0))
        return StepProblem::ZeroStep;
    const double hold = edge.end - edge.time;
    if (!(hold > 0) || actual.t.empty() || actual.t.front() > edge.time)
        return StepProblem::TooShort;
    // Means and crossings read samples of this hold only: a straight line to a sample after the
    // next step (or before this one) would smear that step into this hold.
    const std::size_t first = firstAfter(actual, edge.time); // ≥ 1: t.front() ≤ time
    const std::size_t end = firstAfter(actual, edge.end);    // one past the hold's samples
    const double finalFrom = edge.end - kFinalShare * hold;
    const double last = actual.t[end - 1];
    if (!(last > finalFrom))
        return StepProblem::TooShort;
    const std::size_t finalBegin = indexFrom(actual.t, finalFrom);
    if (end < first + kMinHoldSamples || end < finalBegin + kMinFinalSamples)
        return StepProblem::TooFewSamples;

    const double start =
        edge.holdBefore > 0
            ? meanOver(actual, edge.time - kFinalShare * edge.holdBefore, actual.t[first - 1])
            : actual.y[first - 1];
    const double settled = meanOver(actual, finalFrom, last);
    const double span = settled - start;
    const auto [lo, hi] =
        std::minmax_element(actual.y.begin() + static_cast<std::ptrdiff_t>(finalBegin),
                            actual.y.begin() + static_cast<std::ptrdiff_t>(end));
    if (!(std::abs(span) > *hi - *lo))
        return StepProblem::NoResponse;
    const double drift = driftAcross(actual, finalBegin, end, last - finalFrom);
    if (!(std::abs(drift) <= kDriftLimit * std::abs(span)))
        return StepProblem::NotSettled;

    const Response r(actual, edge.time, start, span, first, end - 1);
    StepMetrics m;
    m.up = edge.to > edge.from;
    m.from = edge.from;
    m.to = edge.to;
    m.stepTime = edge.time;
    m.startValue = start;
    m.finalValue = settled;
    m.deadTime = r.firstReaching(kDeadLevel) - edge.time;
    m.rise10Time = r.firstReaching(0.1);
    m.rise90Time = r.firstReaching(0.9);
    m.riseTime = m.rise90Time - m.rise10Time;
    const std::size_t peak = r.peakIndex();
    m.peakValue = actual.y[peak];
    m.peakTime = actual.t[peak] - edge.time;
    m.overshootPct = std::max(0.0, r.s(peak) - 1.0) * 100.0;
    m.settlingTime2 = r.settledFrom(0.02) - edge.time;
    m.settlingTime5 = r.settledFrom(0.05) - edge.time;
    m.steadyStateError = edge.to - settled;
    return m;
}

std::string_view stepProblemKey(StepProblem problem)
{
    switch (problem) {
    case StepProblem::TooFewSamples: return "too-few-samples";
    case StepProblem::TooShort: return "too-short";
    case StepProblem::ZeroStep: return "zero-step";
    case StepProblem::NoResponse: return "no-response";
    case StepProblem::NotSettled: return "not-settled";
    }
    return "too-short";
}

} // namespace vt::model
