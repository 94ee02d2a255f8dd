#include "sim/open_loop_plant.h"

namespace vt::dev::sim {

namespace {
// DMA Profinet manual §4.5.1.1 error 3: "Excess current or short circuit at the output stages
// (peak current >8A!)".
constexpr double kShortCircuitPeak = 8.0; // A
} // namespace

PlantErrors outputStageErrors(const ValveChain &chain)
{
    PlantErrors errors;
    for (const CurrentController *stage : {&chain.solenoidA(), &chain.solenoidB()}) {
        if (stage->current() > kShortCircuitPeak)
            errors.set(PlantError::OutputShortCircuit);
        if (stage->deviationError())
            errors.set(PlantError::OutputCurrentDeviation);
    }
    return errors;
}

OpenLoopPlant::OpenLoopPlant(const Dictionary &dict, const ParamSource &params, ParamSink &display,
                             PlantConfig config)
    : m_params(params), m_out(display), m_table(errorTableFor(dict)),
      m_path(SetValuePathIds::resolve(dict, config.branch)),
      m_chain(ValveChainIds::resolve(dict, config.branch), config.currents)
{
}

void OpenLoopPlant::setAnalogueInput(AnalogueInput input, double physical)
{
    m_path.inputs().setInput(input, physical);
}

void OpenLoopPlant::setSolenoidFault(bool solenoidB, SolenoidFault fault)
{
    (solenoidB ? m_chain.solenoidB() : m_chain.solenoidA()).setFault(fault);
}

void OpenLoopPlant::step(const SimStep &step)
{
    const bool outputsOn = m_enabled && !m_errors.tripped();
    const SetValuePathValues &sv = m_path.step(m_params, outputsOn, step.dt());
    m_chain.step(sv.postRamp, outputsOn, m_params, step.dt(), step.timeUs);

    PlantErrors present = sv.errors;
    present |= outputStageErrors(m_chain);
    m_errors.update(present);

    m_path.publish(m_out);
    m_chain.publish(m_out);
}

} // namespace vt::dev::sim
