#include "sim/closed_loop_plant.h"

namespace vt::dev::sim {

ClosedLoopIds ClosedLoopIds::resolve(const Dictionary &dict, int branch)
{
    auto b = [&](std::string_view name) { return findParam(dict, branchName(name, branch)); };
    ClosedLoopIds ids;
    ids.controller = b("C1.00");
    ids.sensor = b("C1.09");
    ids.feedbackGain = b("C1.10");
    ids.feedbackOffset = b("C1.11");
    ids.feedbackSign = b("C1.12");
    ids.kp1 = b("C1.13");
    ids.pt1Time = b("C1.14");
    ids.threshold = b("C1.15");
    ids.kp2 = b("C1.16");
    ids.ki = b("C1.17");
    ids.kd = b("C1.18");
    ids.dt1Time = b("C1.19");
    ids.pGain = b("C1.20");
    ids.fractureDetection = b("C1.26");
    ids.iLimit = b("C1.33");
    ids.negativeGain = b("C1.36");
    ids.busFeedback = b("A1.02");
    ids.desired = b("d1.10");
    ids.actual = b("d1.11");
    ids.lagError = b("d1.12");
    ids.output = b("d1.13");
    return ids;
}

ClosedLoopPlant::ClosedLoopPlant(const Dictionary &dict, const ParamSource &params,
                                 ParamSink &display, std::unique_ptr<AxisModel> axis,
                                 PlantConfig config, ValveConstants valve)
    : m_params(params), m_out(display), m_table(errorTableFor(dict)), m_branch(config.branch),
      m_ids(ClosedLoopIds::resolve(dict, config.branch)),
      m_path(SetValuePathIds::resolve(dict, config.branch)),
      m_chain(ValveChainIds::resolve(dict, config.branch), config.currents), m_valve(valve),
      m_axis(axis ? std::move(axis) : std::make_unique<CylinderAxis>())
{
}

void ClosedLoopPlant::setAnalogueInput(AnalogueInput input, double physical)
{
    m_path.inputs().setInput(input, physical);
}

void ClosedLoopPlant::setSolenoidFault(bool solenoidB, SolenoidFault fault)
{
    (solenoidB ? m_chain.solenoidB() : m_chain.solenoidA()).setFault(fault);
}

LoopSettings ClosedLoopPlant::loopSettings() const
{
    LoopSettings s;
    s.kp1 = m_params.value(m_ids.kp1, 1.0);
    s.pt1Time = m_params.seconds(m_ids.pt1Time, 0.0);
    s.threshold = m_params.value(m_ids.threshold, 0.0);
    s.kp2 = m_params.value(m_ids.kp2, 1.0);
    s.ki = m_params.value(m_ids.ki, 0.0);
    s.kd = m_params.value(m_ids.kd, 0.0);
    s.dt1Time = m_params.seconds(m_ids.dt1Time, 0.0);
    s.pGain = m_params.value(m_ids.pGain, 1.0);
    // DMA V15 and V31 have no C1.33: their I-portion is limited only by the output range.
    s.iLimit = m_params.value(m_ids.iLimit, LoopController::kOutputLimit);
    if (const auto type = SensorType::fromSelection(m_params.raw(m_ids.sensor, 0)))
        s.positiveOnly = type->positiveOnly;
    return s;
}

FeedbackSettings ClosedLoopPlant::feedbackSettings() const
{
    FeedbackSettings s;
    s.sensor = m_params.raw(m_ids.sensor, 0);
    s.gain = m_params.value(m_ids.feedbackGain, 1.0);
    s.negativeGain = m_params.value(m_ids.negativeGain, 1.0);
    s.offset = m_params.value(m_ids.feedbackOffset, 0.0);
    s.sign = m_params.raw(m_ids.feedbackSign, 1);
    s.fractureDetection = m_params.raw(m_ids.fractureDetection, 0);
    s.busFeedback = m_params.value(m_ids.busFeedback, 0.0);
    return s;
}

bool ClosedLoopPlant::loopWanted(bool outputsOn) const
{
    if (!outputsOn)
        return false;
    // C1.00: 0 off (open loop), 1 P-PT1-I-DT1, 2 remote, 3 dff, 4 remote + dff. The remote loop
    // controller closes the loop while Din is set (DMA Profinet manual §4.5.1.3 Dout_1; the
    // comparator KOMP_1 condition belongs to the module's comparators). ASSUMPTION: "dff" is
    // not described anywhere; 3/4 run the same controller as 1/2.
    switch (m_params.raw(m_ids.controller, 1)) {
    case 1:
    case 3: return true;
    case 2:
    case 4: return m_din;
    default: return false;
    }
}

void ClosedLoopPlant::step(const SimStep &step)
{
    const double dt = step.dt();
    const bool outputsOn = m_enabled && !m_errors.tripped();
    const SetValuePathValues &sv = m_path.step(m_params, outputsOn, dt);

    const bool closed = loopWanted(outputsOn);
    const FeedbackReading fb =
        readFeedback(feedbackSettings(), m_axis->measured(), m_sensorFault, closed);
    m_loop.desired = sv.postRamp;
    m_loop.actual = fb.volts;
    m_loop.closed = closed;
    double valveInput = sv.postRamp; // open loop: the set value drives the valve directly
    if (closed) {
        m_loop.lagError = m_loop.desired - m_loop.actual;
        m_loop.output = m_controller.step(m_loop.lagError, loopSettings(), dt);
        valveInput = m_loop.output;
    } else {
        // "d1.12 and d1.13 remain at 0.000 V as long as the condition for activation Din_1 has
        // not been set" (DMA Profinet manual §4.5.1.3); the controller restarts from rest.
        m_controller.reset();
        m_loop.lagError = 0.0;
        m_loop.output = 0.0;
    }
    m_chain.step(valveInput, outputsOn, m_params, dt, step.timeUs);
    m_valve.step(m_chain.values().spoolCommand, dt);
    m_axis->step(m_valve.flow(), dt);

    PlantErrors present = sv.errors;
    present |= outputStageErrors(m_chain);
    if (fb.fracture)
        present.set(PlantError::FeedbackCableFracture);
    if (fb.overload)
        present.set(PlantError::FeedbackOverload);
    m_errors.update(present);

    m_path.publish(m_out);
    m_chain.publish(m_out);
    m_out.publish(m_ids.desired, m_loop.desired);
    m_out.publish(m_ids.actual, m_loop.actual);
    m_out.publish(m_ids.lagError, m_loop.lagError);
    m_out.publish(m_ids.output, m_loop.output);
}

} // namespace vt::dev::sim
