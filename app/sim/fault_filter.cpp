// FaultFilter: see fault_filter.h. The draws mirror FaultLink::inject so a spec means the same
// on a link and in the simulator.
#include "fault_filter.h"

namespace vt::simapp {
namespace {

// Uniform in [0, 1) from one raw draw; std::uniform_real_distribution is implementation-defined.
double unit(std::uint32_t draw)
{
    return static_cast<double>(draw) / 4294967296.0;
}

} // namespace

FaultFilter::FaultFilter(const link::FaultRates &rates, std::optional<std::uint64_t> cutAfter,
                         std::uint32_t seed)
    : m_rates(rates), m_cutAfter(cutAfter), m_rng(seed)
{
}

FaultFilter::Verdict FaultFilter::push(Bytes answer, std::int64_t nowUs)
{
    if (m_cutAfter && m_answers >= *m_cutAfter)
        return Verdict::AfterCut;
    ++m_answers;

    const std::uint32_t dropDraw = static_cast<std::uint32_t>(m_rng());
    const std::uint32_t corruptDraw = static_cast<std::uint32_t>(m_rng());
    const std::uint32_t positionDraw = static_cast<std::uint32_t>(m_rng());
    const std::uint32_t flipDraw = static_cast<std::uint32_t>(m_rng());
    if (unit(dropDraw) < m_rates.drop)
        return Verdict::Dropped;

    Held h;
    if (!answer.empty() && unit(corruptDraw) < m_rates.corrupt) {
        const std::size_t at = positionDraw % answer.size();
        // 1..255: the byte always changes.
        answer[at] = static_cast<std::uint8_t>(answer[at] ^ (1 + flipDraw % 255));
        h.answer.corrupted = true;
    }
    h.answer.bytes = std::move(answer);
    h.answer.delayed = m_rates.delayMs > 0;
    h.dueUs = nowUs + std::int64_t{m_rates.delayMs} * 1000;
    m_held.push_back(std::move(h));
    return Verdict::Passed;
}

std::vector<FaultFilter::Answer> FaultFilter::release(std::int64_t nowUs)
{
    std::vector<Answer> out;
    while (!m_held.empty() && m_held.front().dueUs <= nowUs) {
        out.push_back(std::move(m_held.front().answer));
        m_held.pop_front();
    }
    return out;
}

std::optional<std::int64_t> FaultFilter::nextDueUs() const
{
    if (m_held.empty())
        return std::nullopt;
    return m_held.front().dueUs;
}

} // namespace vt::simapp
