// Why the analysis has no figures, as sentences for people (the analysis itself keeps stable
// English keys: step_metrics.h, frequency_response.h). GUI thread.
#pragma once

#include "model/tuning/frequency_response.h"
#include "model/tuning/step_metrics.h"

#include <QCoreApplication>
#include <QString>

namespace vt::ui {

// The tr() context of these texts.
class AnalysisTexts
{
    Q_DECLARE_TR_FUNCTIONS(AnalysisTexts)
};

QString stepProblemText(model::StepProblem problem);
QString frequencyProblemText(model::FrequencyProblem problem);

} // namespace vt::ui
