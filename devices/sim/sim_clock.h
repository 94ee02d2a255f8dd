// SimClock: simulated time of the device simulator in whole microseconds. advance() steps the
// registered models in fixed internal steps, so a trajectory never depends on how the caller
// chunks time (the app drives it from a real-time timer, tests as fast as they can).
// Owner: whoever builds the simulator; single-threaded, not shared between threads.
#pragma once

#include <cstdint>
#include <vector>

namespace vt::dev::sim {

// One fixed integration step as the models see it.
struct SimStep
{
    std::int64_t timeUs = 0; // simulated time at the END of this step
    std::int64_t stepUs = 0; // length of the step

    double dt() const { return static_cast<double>(stepUs) * 1e-6; }
};

// Anything the clock integrates. The model must not keep the SimStep beyond the call.
class SimModel
{
public:
    virtual ~SimModel() = default;
    virtual void step(const SimStep &step) = 0;
};

class SimClock
{
public:
    // 0.5 ms: six steps per 3 ms current-controller time constant and more than six samples per
    // cycle of the highest dither frequency (E14 max. 300 Hz).
    static constexpr std::int64_t kDefaultStepUs = 500;

    explicit SimClock(std::int64_t stepUs = kDefaultStepUs);

    // Models are stepped in the order they were attached. The clock does not own them; detach
    // before destroying a model.
    void attach(SimModel &model);
    void detach(SimModel &model);

    // Moves the caller's time on by dtUs (negative values are ignored) and runs every whole step
    // that now fits. The part of a step not yet covered waits for the next call, so
    // advance(1000) == advance(300) + advance(700), bit for bit.
    void advance(std::int64_t dtUs);
    // Same, to an absolute time; earlier times are ignored (time never runs backwards).
    void advanceTo(std::int64_t timeUs);

    std::int64_t nowUs() const { return m_nowUs; } // the caller's time
    std::int64_t steppedUs() const
    {
        return m_stepsDone * m_stepUs;
    } // time the models have reached
    std::int64_t stepUs() const { return m_stepUs; }
    std::int64_t stepsDone() const { return m_stepsDone; }

private:
    std::int64_t m_stepUs;
    std::int64_t m_nowUs = 0;
    std::int64_t m_stepsDone = 0;
    std::vector<SimModel *> m_models;
};

} // namespace vt::dev::sim
