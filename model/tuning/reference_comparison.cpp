#include "reference_comparison.h"

#include "dict/cooking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace vt::model {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double field(const std::optional<StepMetrics> &m, double StepMetrics::*member)
{
    return m ? (*m).*member : kNaN;
}

} // namespace

std::string_view driftMetricKey(DriftMetric metric)
{
    switch (metric) {
    case DriftMetric::RiseTime: return "rise-time";
    case DriftMetric::Overshoot: return "overshoot";
    case DriftMetric::SettlingTime: return "settling-time";
    case DriftMetric::SteadyStateError: return "steady-state-error";
    case DriftMetric::Bandwidth: return "bandwidth";
    case DriftMetric::Phase90: return "phase-90";
    }
    return "rise-time";
}

std::string_view driftMetricLabel(DriftMetric metric)
{
    switch (metric) {
    case DriftMetric::RiseTime: return "rise time 10-90 %";
    case DriftMetric::Overshoot: return "overshoot";
    case DriftMetric::SettlingTime: return "settling time 2 %";
    case DriftMetric::SteadyStateError: return "steady-state error";
    case DriftMetric::Bandwidth: return "bandwidth (-3 dB)";
    case DriftMetric::Phase90: return "frequency at -90 deg";
    }
    return "";
}

double DriftThresholds::of(DriftMetric metric) const
{
    switch (metric) {
    case DriftMetric::RiseTime: return riseTimePct;
    case DriftMetric::Overshoot: return overshootPoints;
    case DriftMetric::SettlingTime: return settlingPct;
    case DriftMetric::SteadyStateError: return steadyStatePctOfStep;
    case DriftMetric::Bandwidth: return bandwidthPct;
    case DriftMetric::Phase90: return phase90Pct;
    }
    return 0;
}

bool ReferenceComparison::exceeded() const
{
    return std::any_of(metrics.begin(), metrics.end(),
                       [](const MetricDrift &m) { return m.exceeded; });
}

MetricDrift metricDrift(DriftMetric metric, double reference, double now,
                        const DriftThresholds &thresholds, double stepHeight)
{
    MetricDrift d;
    d.metric = metric;
    d.label = driftMetricLabel(metric);
    d.reference = reference;
    d.now = now;
    d.thresholdPercent = thresholds.of(metric);
    const bool hadIt = std::isfinite(reference);
    const bool hasIt = std::isfinite(now);
    if (!hadIt || !hasIt) {
        // A figure that is gone now (the step no longer settles …) is drift; one that appeared
        // is not.
        d.deltaPercent = kNaN;
        d.exceeded = hadIt && !hasIt;
        return d;
    }
    switch (metric) {
    case DriftMetric::Overshoot:
        d.deltaPercent = now - reference;
        d.exceeded = d.deltaPercent > d.thresholdPercent;
        return d;
    case DriftMetric::SteadyStateError:
        d.deltaPercent = stepHeight > 0 ? (now - reference) / stepHeight * 100 : kNaN;
        break;
    default:
        d.deltaPercent = reference != 0 ? (now - reference) / std::abs(reference) * 100
                         : now == 0     ? 0
                                        : kNaN;
        break;
    }
    d.exceeded = !std::isfinite(d.deltaPercent) || std::abs(d.deltaPercent) > d.thresholdPercent;
    return d;
}

std::vector<MetricDrift> stepDrift(const std::optional<StepMetrics> &reference,
                                   const std::optional<StepMetrics> &now,
                                   const DriftThresholds &thresholds, const std::string &unit)
{
    const double height = reference ? std::abs(reference->to - reference->from)
                                    : (now ? std::abs(now->to - now->from) : 0.0);
    std::vector<MetricDrift> out;
    const auto add = [&](DriftMetric metric, double StepMetrics::*member, std::string u) {
        out.push_back(
            metricDrift(metric, field(reference, member), field(now, member), thresholds, height));
        out.back().unit = std::move(u);
    };
    add(DriftMetric::RiseTime, &StepMetrics::riseTime, "s");
    add(DriftMetric::Overshoot, &StepMetrics::overshootPct, "%");
    add(DriftMetric::SettlingTime, &StepMetrics::settlingTime2, "s");
    add(DriftMetric::SteadyStateError, &StepMetrics::steadyStateError, unit);
    return out;
}

std::vector<MetricDrift> sweepDrift(double referenceF3dB, double nowF3dB, double referenceF90,
                                    double nowF90, const DriftThresholds &thresholds)
{
    std::vector<MetricDrift> out{
        metricDrift(DriftMetric::Bandwidth, referenceF3dB, nowF3dB, thresholds),
        metricDrift(DriftMetric::Phase90, referenceF90, nowF90, thresholds)};
    for (MetricDrift &m : out)
        m.unit = "Hz";
    return out;
}

std::vector<ParamDrift> paramDrift(int module, const dev::Dictionary &dictionary,
                                   const std::vector<RunSetting> &reference,
                                   const std::vector<RunSetting> &now, dev::Language language)
{
    std::map<std::string, double> was;
    std::map<std::string, double> is;
    for (const RunSetting &s : reference)
        was[s.name] = s.raw;
    for (const RunSetting &s : now)
        is[s.name] = s.raw;
    std::vector<ParamDrift> out;
    const auto differs = [&](const std::string &name) {
        const auto a = was.find(name);
        const auto b = is.find(name);
        if (a == was.end() && b == is.end())
            return false;
        return a == was.end() || b == is.end() || a->second != b->second;
    };
    const auto entry = [&](const std::string &name, const dev::ParamMeta *row) {
        ParamDrift d;
        d.module = module;
        d.row = name;
        d.name = row ? row->label.in(language) : std::string();
        if (d.name.empty())
            d.name = name;
        d.unit = row ? row->unit : std::string();
        if (const auto a = was.find(name); a != was.end()) {
            d.referenceRaw = a->second;
            d.reference = row ? dev::toDisplay(*row, a->second) : a->second;
        }
        if (const auto b = is.find(name); b != is.end()) {
            d.nowRaw = b->second;
            d.now = row ? dev::toDisplay(*row, b->second) : b->second;
        }
        out.push_back(std::move(d));
    };
    for (const dev::ParamMeta &row : dictionary.params)
        if (differs(row.name)) {
            entry(row.name, &row);
            was.erase(row.name);
            is.erase(row.name);
        }
    std::map<std::string, bool> rest; // rows the dictionary does not know, in name order
    for (const auto &[name, raw] : was)
        rest[name] = true;
    for (const auto &[name, raw] : is)
        rest[name] = true;
    for (const auto &[name, unused] : rest)
        if (differs(name))
            entry(name, nullptr);
    return out;
}

DriftOverlay stepOverlay(std::string test, const Samples &reference, const StepEdge &referenceEdge,
                         const Samples &now, const StepEdge &nowEdge, std::size_t points)
{
    DriftOverlay o;
    o.test = std::move(test);
    const double hold =
        std::min(referenceEdge.end - referenceEdge.time, nowEdge.end - nowEdge.time);
    if (!(hold > 0) || points < 2 || reference.t.empty() || now.t.empty())
        return o;
    const double lead = std::min(hold / 10, std::min(referenceEdge.holdBefore, nowEdge.holdBefore));
    const double span = lead + hold;
    for (std::size_t i = 0; i < points; ++i) {
        const double x = -lead + span * static_cast<double>(i) / static_cast<double>(points - 1);
        o.x.push_back(x);
        o.reference.push_back(valueAt(reference, referenceEdge.time + x));
        o.now.push_back(valueAt(now, nowEdge.time + x));
    }
    return o;
}

} // namespace vt::model
