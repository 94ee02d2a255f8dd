// The reference comparison's words for people: a test's name and a figure's name, in the language
// in force. Shared by the Workbench's drift view and the commissioning report; tr() context
// vt::ui::ReferenceDriftView (where they were first said). GUI thread.
#pragma once

#include "model/tuning/reference_comparison.h"

#include <QCoreApplication>
#include <QString>
#include <string>

namespace vt::model {

class DriftTexts
{
    Q_DECLARE_TR_FUNCTIONS(vt::ui::ReferenceDriftView)
public:
    static QString test(const std::string &test); // "step-up" → "step up"
    static QString metric(DriftMetric metric);    // "rise time 10–90 %"
};

} // namespace vt::model
