#include "analysis_texts.h"

namespace vt::model {

QString stepProblemText(StepProblem problem)
{
    switch (problem) {
    case StepProblem::TooFewSamples:
        return AnalysisTexts::tr("no figures: too few samples in the hold");
    case StepProblem::TooShort: return AnalysisTexts::tr("no figures: the hold is too short");
    case StepProblem::ZeroStep: return AnalysisTexts::tr("no figures: no step");
    case StepProblem::NoResponse: return AnalysisTexts::tr("no figures: the response did not move");
    case StepProblem::NotSettled:
        return AnalysisTexts::tr("no figures: not settled by the end of the hold");
    }
    return {};
}

QString frequencyProblemText(FrequencyProblem problem)
{
    switch (problem) {
    case FrequencyProblem::None: return {};
    case FrequencyProblem::BadRequest: return AnalysisTexts::tr("no: not measurable");
    case FrequencyProblem::OutsideRecording: return AnalysisTexts::tr("no: outside the recording");
    case FrequencyProblem::TooFewSamples: return AnalysisTexts::tr("no: too few samples");
    case FrequencyProblem::NoExcitation: return AnalysisTexts::tr("no: the set value did not move");
    case FrequencyProblem::AboveValidBand: return AnalysisTexts::tr("no: above the valid band");
    }
    return {};
}

} // namespace vt::model
