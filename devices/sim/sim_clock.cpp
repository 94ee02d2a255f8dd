#include "sim/sim_clock.h"

#include <algorithm>

namespace vt::dev::sim {

SimClock::SimClock(std::int64_t stepUs) : m_stepUs(stepUs > 0 ? stepUs : kDefaultStepUs)
{
}

void SimClock::attach(SimModel &model)
{
    if (std::find(m_models.begin(), m_models.end(), &model) == m_models.end())
        m_models.push_back(&model);
}

void SimClock::detach(SimModel &model)
{
    m_models.erase(std::remove(m_models.begin(), m_models.end(), &model), m_models.end());
}

void SimClock::advance(std::int64_t dtUs)
{
    if (dtUs <= 0)
        return;
    m_nowUs += dtUs;
    // Steps are counted, not accumulated as time: the step times are exact multiples of the
    // step length whatever the call pattern, which is what makes chunking irrelevant.
    while ((m_stepsDone + 1) * m_stepUs <= m_nowUs) {
        ++m_stepsDone;
        const SimStep step{m_stepsDone * m_stepUs, m_stepUs};
        for (SimModel *model : m_models)
            model->step(step);
    }
}

void SimClock::advanceTo(std::int64_t timeUs)
{
    advance(timeUs - m_nowUs);
}

} // namespace vt::dev::sim
