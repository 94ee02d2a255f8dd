#include "analysis_texts.h"

namespace vt::ui {

QString stepProblemText(model::StepProblem problem)
{
    switch (problem) {
    case model::StepProblem::TooFewSamples:
        return AnalysisTexts::tr("no figures: too few samples in the hold");
    case model::StepProblem::TooShort:
        return AnalysisTexts::tr("no figures: the hold is too short");
    case model::StepProblem::ZeroStep: return AnalysisTexts::tr("no figures: no step");
    case model::StepProblem::NoResponse:
        return AnalysisTexts::tr("no figures: the response did not move");
    case model::StepProblem::NotSettled:
        return AnalysisTexts::tr("no figures: not settled by the end of the hold");
    }
    return {};
}

QString frequencyProblemText(model::FrequencyProblem problem)
{
    switch (problem) {
    case model::FrequencyProblem::None: return {};
    case model::FrequencyProblem::BadRequest: return AnalysisTexts::tr("no: not measurable");
    case model::FrequencyProblem::OutsideRecording:
        return AnalysisTexts::tr("no: outside the recording");
    case model::FrequencyProblem::TooFewSamples: return AnalysisTexts::tr("no: too few samples");
    case model::FrequencyProblem::NoExcitation:
        return AnalysisTexts::tr("no: the set value did not move");
    case model::FrequencyProblem::AboveValidBand:
        return AnalysisTexts::tr("no: above the valid band");
    }
    return {};
}

} // namespace vt::ui
