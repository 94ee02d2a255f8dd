#include "gain_search.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

std::string_view key(GainVerdict verdict)
{
    switch (verdict) {
    case GainVerdict::Measure: return "measure";
    case GainVerdict::Reached: return "reached";
    case GainVerdict::Exhausted: return "exhausted";
    case GainVerdict::Unreachable: return "unreachable";
    }
    return "measure";
}

GainSearch::GainSearch(GainTarget target, Gains start, double pMin, double pMax, int maxIterations)
    : m_target(target), m_pMin(std::max(1.0, std::min(pMin, pMax))), m_pMax(std::max(pMin, pMax)),
      m_maxIterations(std::max(1, maxIterations)), m_i(start.i)
{
}

double GainSearch::limitPct() const
{
    return m_target.kind == GainTarget::Kind::FastestWithoutOvershoot
               ? kNoOvershootPct
               : std::max(0.0, m_target.maxOvershootPct);
}

bool GainSearch::accepted(double overshootPct) const
{
    // Fastest without overshoot has no band: every soft gain is "without"; only the bracket ends
    // it.
    if (m_target.kind == GainTarget::Kind::FastestWithoutOvershoot)
        return false;
    const double limit = limitPct();
    return overshootPct <= limit && overshootPct >= limit * (1 - kAcceptShare);
}

GainProposal GainSearch::measured(const Gains &gains, double overshootPct)
{
    const GainMeasurement m{gains, std::isnan(overshootPct) ? 0 : overshootPct};
    m_history.push_back(m);
    const bool within = m.overshootPct <= limitPct();
    if (within && (!m_low || gains.p > m_low->gains.p))
        m_low = m;
    if (!within && (!m_high || gains.p < m_high->gains.p))
        m_high = m;

    GainProposal out;
    if (m_low)
        out.best = m_low->gains;
    if (within && accepted(m.overshootPct)) {
        out.verdict = GainVerdict::Reached;
        return out;
    }
    if (within && gains.p >= m_pMax) {
        out.verdict = GainVerdict::Reached; // the stiffest gain allowed stays within the limit
        return out;
    }
    if (!within && gains.p <= m_pMin && !m_low) {
        out.verdict = GainVerdict::Unreachable;
        return out;
    }
    if (m_low && m_high &&
        m_high->gains.p - m_low->gains.p <= std::max(1.0, kResolution * m_low->gains.p)) {
        out.verdict = GainVerdict::Reached; // resolved: the highest gain within the limit
        return out;
    }
    if (static_cast<int>(m_history.size()) >= m_maxIterations) {
        out.verdict = GainVerdict::Exhausted;
        return out;
    }
    return propose(gains);
}

GainProposal GainSearch::propose(const Gains &at) const
{
    GainProposal out;
    out.verdict = GainVerdict::Measure;
    if (m_low)
        out.best = m_low->gains;
    double p = at.p;
    if (m_low && m_high)
        p = std::round((m_low->gains.p + m_high->gains.p) / 2);
    else if (m_high)
        p = std::floor(m_high->gains.p / 2);
    else
        p = std::ceil(m_low->gains.p * 2);
    out.next = Gains{std::clamp(p, m_pMin, m_pMax), m_i};
    return out;
}

} // namespace vt::model
