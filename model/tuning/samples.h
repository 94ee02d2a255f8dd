// Samples: one recorded channel — times in seconds, ascending, and the values, same length.
// Plain C++ so the analysis stays free of Qt.
#pragma once

#include <vector>

namespace vt::model {

struct Samples
{
    std::vector<double> t;
    std::vector<double> y;
};

} // namespace vt::model
