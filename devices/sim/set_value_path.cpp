#include "sim/set_value_path.h"

#include <algorithm>

namespace vt::dev::sim {

SetValuePathIds SetValuePathIds::resolve(const Dictionary &dict, int branch)
{
    SetValuePathIds ids;
    ids.inputs = SetValueIds::resolve(dict, branch);
    const std::array<const char *, 4> ramps{"r1.01", "r1.02", "r1.03", "r1.04"};
    for (std::size_t i = 0; i < ramps.size(); ++i)
        ids.ramps[i] = findParam(dict, branchName(ramps[i], branch));
    ids.rampSelection = findParam(dict, "E08");
    ids.sum = findParam(dict, branchName("d1.01", branch));
    ids.postRamp = findParam(dict, branchName("d1.02", branch));
    return ids;
}

SetValuePath::SetValuePath(SetValuePathIds ids) : m_ids(std::move(ids)), m_inputs(m_ids.inputs)
{
}

const SetValuePathValues &SetValuePath::step(const ParamReader &params, bool enabled, double dt)
{
    const SetValueSum sum = m_inputs.evaluate(params);
    m_values.sum = std::clamp(sum.total(), -9.999, 9.999);
    m_values.errors = sum.errors;
    if (!enabled) {
        m_ramp.reset();
        m_values.postRamp = 0.0;
        return m_values;
    }
    const RampTimes times{params.seconds(m_ids.ramps[0], 0.0), params.seconds(m_ids.ramps[1], 0.0),
                          params.seconds(m_ids.ramps[2], 0.0), params.seconds(m_ids.ramps[3], 0.0)};
    double out = 0.0;
    if (params.raw(m_ids.rampSelection, 0) == 1) {
        // E08 = 1: "all set values (rise constant)".
        out = m_ramp.step(m_values.sum, times, RampKind::RiseConstant, dt);
    } else {
        // E08 = 0: "digital set values (time constant)"; the analogue inputs pass unramped.
        out =
            m_ramp.step(std::clamp(sum.digital, -9.999, 9.999), times, RampKind::TimeConstant, dt) +
            sum.analogue;
    }
    m_values.postRamp = std::clamp(out, -9.999, 9.999);
    return m_values;
}

void SetValuePath::publish(ParamPublisher &out) const
{
    out.publish(m_ids.sum, m_values.sum);
    out.publish(m_ids.postRamp, m_values.postRamp);
}

} // namespace vt::dev::sim
