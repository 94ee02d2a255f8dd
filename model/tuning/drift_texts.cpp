#include "model/tuning/drift_texts.h"

namespace vt::model {

QString DriftTexts::test(const std::string &test)
{
    if (test == "step-up")
        return tr("step up");
    if (test == "step-down")
        return tr("step down");
    if (test == "sweep")
        return tr("sweep");
    if (test == "steps")
        return tr("steps");
    return QString::fromStdString(test);
}

QString DriftTexts::metric(DriftMetric metric)
{
    switch (metric) {
    case DriftMetric::RiseTime: return tr("rise time 10–90 %");
    case DriftMetric::Overshoot: return tr("overshoot");
    case DriftMetric::SettlingTime: return tr("settling time 2 %");
    case DriftMetric::SteadyStateError: return tr("steady-state error");
    case DriftMetric::Bandwidth: return tr("bandwidth (−3 dB)");
    case DriftMetric::Phase90: return tr("frequency at −90°");
    }
    return {};
}

} // namespace vt::model
