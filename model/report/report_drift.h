// The reference fingerprint's comparison (model/tuning/reference_comparison.h) as the report's
// drift section, in the report's language: parameter names from the dictionary, values as the
// editor shows them, the figures and tests named as the Workbench names them, and the step
// responses (reference and now) as overlay curves. Call it while the report's words are in force
// (the GUI's ReportWords, the CLI's --lang). GUI thread.
#pragma once

#include "model/report/report_data.h"
#include "model/tuning/reference_fingerprint.h"

namespace vt::model {

ReportDrift reportDrift(const Reference &reference, const ReferenceComparison &comparison,
                        const QString &file, const dev::Dictionary *dictionary, dev::Language lang);

} // namespace vt::model
