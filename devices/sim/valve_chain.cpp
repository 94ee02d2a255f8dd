#include "sim/valve_chain.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace vt::dev::sim {

namespace {

// "2.7 A", "0.630 A" -> 2.7, 0.63; nothing when the label does not start with a number.
std::optional<double> labelCurrent(const std::string &label)
{
    const char *begin = label.c_str();
    char *end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || value <= 0.0)
        return std::nullopt;
    return value;
}

std::map<std::int64_t, double> ratedCurrents(const ParamRef &selection)
{
    std::map<std::int64_t, double> out;
    if (!selection.meta)
        return out;
    for (const EnumLabel &e : selection.meta->enums)
        if (auto amps = labelCurrent(e.text.en))
            out[e.value] = *amps;
    return out;
}

bool containsCustom(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text.find("custom") != std::string::npos;
}

double rated(const std::map<std::int64_t, double> &table, const ParamRef &selection,
             const ParamReader &params)
{
    const auto value =
        params.raw(selection, selection.meta && selection.meta->defaultValue
                                  ? static_cast<std::int32_t>(*selection.meta->defaultValue)
                                  : 0);
    auto it = table.find(value);
    return it == table.end() ? ValveChain::kFallbackRatedCurrent : it->second;
}

} // namespace

ValveChainIds ValveChainIds::resolve(const Dictionary &dict, int branch)
{
    auto b = [&](std::string_view name) { return findParam(dict, branchName(name, branch)); };
    ValveChainIds ids;
    ids.linearisation = b("C1.02");
    for (std::size_t i = 0; i < ids.curveX.size(); ++i) {
        ids.curveX[i] = b("L1.x" + std::to_string(i));
        ids.curveY[i] = b("L1.y" + std::to_string(i));
    }
    ids.gainA = b("C1.03");
    ids.gainB = b("C1.04");
    ids.signGain = b("C1.05");
    ids.offset = b("C1.06");
    ids.deadBandA = b("C1.07");
    ids.deadBandB = b("C1.08");
    // The output stage rows exist once per module (E block, no branch digit in the OPAT names);
    // ASSUMPTION: a second branch (OPAT modes 6/8) drives a valve of the same solenoid selection.
    ids.solenoidA = findParam(dict, {"E1.03", "E03"});
    ids.solenoidB = findParam(dict, "E2.03");
    ids.adaptationA = findParam(dict, {"E1.10", "E10"});
    ids.adaptationB = findParam(dict, "E2.10");
    ids.initialA = findParam(dict, "E11");
    ids.initialB = findParam(dict, "E12");
    ids.ditherAmplitudeA = findParam(dict, {"E1.13", "E13"});
    ids.ditherFrequencyA = findParam(dict, {"E1.14", "E14"});
    ids.ditherAmplitudeB = findParam(dict, "E2.13");
    ids.ditherFrequencyB = findParam(dict, "E2.14");
    ids.afterLinearisation = b("d1.03");
    ids.afterGain = b("d1.04");
    ids.signalA = b("d1.05");
    ids.signalB = b("d1.06");
    ids.currentA = b("d1.07");
    ids.currentB = b("d1.08");
    ids.currentTotal = b("d1.09");
    if (ids.linearisation.meta)
        for (const EnumLabel &e : ids.linearisation.meta->enums)
            if (containsCustom(e.text.en))
                ids.customCurveValue = static_cast<int>(e.value);
    ids.ratedA = ratedCurrents(ids.solenoidA);
    ids.ratedB = ratedCurrents(ids.solenoidB);
    return ids;
}

ValveChain::ValveChain(ValveChainIds ids, CurrentControllerConstants currentConstants)
    : m_ids(std::move(ids)), m_a(currentConstants), m_b(currentConstants)
{
}

void ValveChain::reset()
{
    m_a.reset();
    m_b.reset();
    m_values = {};
}

double ValveChain::ratedCurrentA(const ParamReader &params) const
{
    return rated(m_ids.ratedA, m_ids.solenoidA, params);
}

double ValveChain::ratedCurrentB(const ParamReader &params) const
{
    return rated(m_ids.ratedB, m_ids.solenoidB, params);
}

double ValveChain::linearise(double x, const ParamReader &params) const
{
    const int curve = params.raw(m_ids.linearisation, 0);
    if (curve == 0)
        return x;
    if (curve == m_ids.customCurveValue) {
        CustomCurve points;
        for (std::size_t i = 0; i < points.size(); ++i)
            points[i] = {params.value(m_ids.curveX[i], static_cast<double>(i) * 1.25),
                         params.value(m_ids.curveY[i], static_cast<double>(i) * 1.25)};
        return Linearisation::customCurve(points, x);
    }
    return Linearisation::numberedCurve(curve, x);
}

double ValveChain::deadBand(double magnitude, double compensation)
{
    // The output jumps to the compensation as soon as the value leaves 0 and then rises linearly,
    // so full scale still gives full scale: the solenoid starts where the spool overlap ends
    // ("9.999 V = max. current depending on solenoid selection", OPAT manual §7 ID 0x30 C1.07).
    if (magnitude <= kDeadBandThreshold)
        return 0.0;
    const double c = std::clamp(compensation, 0.0, kFullScale);
    return std::min(c + magnitude * (kFullScale - c) / kFullScale, 9.999);
}

const ValveChainValues &ValveChain::step(double input, bool outputsOn, const ParamReader &params,
                                         double dt, std::int64_t timeUs)
{
    ValveChainValues v;
    const double ratedA = ratedCurrentA(params);
    const double ratedB = ratedCurrentB(params);
    double demandA = 0.0, demandB = 0.0;
    if (outputsOn) {
        v.afterLinearisation = std::clamp(linearise(input, params), -9.999, 9.999);
        // C1.05 "Sign and gain! A negative value inverts the set value", C1.06 the offset, then
        // the gain of the solenoid the value goes to (positive -> A, negative -> B).
        double x = params.value(m_ids.signGain, 1.0) * v.afterLinearisation +
                   params.value(m_ids.offset, 0.0);
        x *= x >= 0.0 ? params.value(m_ids.gainA, 1.0) : params.value(m_ids.gainB, 1.0);
        v.afterGain = std::clamp(x, -9.999, 9.999);
        v.signalA =
            v.afterGain > 0.0 ? deadBand(v.afterGain, params.value(m_ids.deadBandA, 0.0)) : 0.0;
        v.signalB =
            v.afterGain < 0.0 ? deadBand(-v.afterGain, params.value(m_ids.deadBandB, 0.0)) : 0.0;
        // E1.10 "variable adjustment of the max. current"; E11/E12 the initial (quiescent) current,
        // "3.000 V = 30 % of max. rated current": a floor under the drive signal while enabled.
        const double maxA = ratedA * params.value(m_ids.adaptationA, 1.0);
        const double maxB = ratedB * params.value(m_ids.adaptationB, 1.0);
        demandA = maxA * std::max(v.signalA, params.value(m_ids.initialA, 0.0)) / kFullScale;
        demandB = maxB * std::max(v.signalB, params.value(m_ids.initialB, 0.0)) / kFullScale;
    }
    const DitherSettings ditherA{ratedA * params.value(m_ids.ditherAmplitudeA, 0.0) / kFullScale,
                                 params.value(m_ids.ditherFrequencyA, 100.0)};
    const DitherSettings ditherB{ratedB * params.value(m_ids.ditherAmplitudeB, 0.0) / kFullScale,
                                 params.value(m_ids.ditherFrequencyB, 100.0)};
    m_a.step(demandA, ditherA, dt, timeUs);
    m_b.step(demandB, ditherB, dt, timeUs);
    v.currentA = m_a.current();
    v.currentB = m_b.current();
    v.currentTotal = v.currentA + v.currentB;
    // The valve's own rated current moves the spool fully (the selection matches the valve).
    v.spoolCommand = std::clamp(m_a.mean() / ratedA - m_b.mean() / ratedB, -1.0, 1.0);
    m_values = v;
    return m_values;
}

void ValveChain::publish(ParamPublisher &out) const
{
    out.publish(m_ids.afterLinearisation, m_values.afterLinearisation);
    out.publish(m_ids.afterGain, m_values.afterGain);
    out.publish(m_ids.signalA, m_values.signalA);
    out.publish(m_ids.signalB, m_values.signalB);
    out.publish(m_ids.currentA, m_values.currentA);
    out.publish(m_ids.currentB, m_values.currentB);
    out.publish(m_ids.currentTotal, m_values.currentTotal);
}

} // namespace vt::dev::sim
