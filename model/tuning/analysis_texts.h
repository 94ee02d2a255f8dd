// Why the analysis has no figures, as sentences for people (the analysis itself keeps stable
// English keys: step_metrics.h, frequency_response.h). GUI thread. The workbench and the
// commissioning report show them.
#pragma once

#include "model/tuning/frequency_response.h"
#include "model/tuning/step_metrics.h"

#include <QCoreApplication>
#include <QString>

namespace vt::model {

// The tr() context of these texts.
class AnalysisTexts
{
    Q_DECLARE_TR_FUNCTIONS(AnalysisTexts)
};

QString stepProblemText(StepProblem problem);
QString frequencyProblemText(FrequencyProblem problem);

} // namespace vt::model
