#include "workbench_rows.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

std::vector<const dev::ParamMeta *> testSetValueRows(const dev::Dictionary &dictionary,
                                                     const std::string &mode)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const std::string &name : dictionary.monitor.forMode(mode).setValues) {
        const dev::ParamMeta *row = dictionary.find(name);
        if (row && row->writable() && row->readable() && !row->isString())
            rows.push_back(row);
    }
    return rows;
}

const dev::ParamMeta *testSetValueRow(const dev::Dictionary &dictionary, const std::string &mode,
                                      int branch)
{
    const auto rows = testSetValueRows(dictionary, mode);
    for (const dev::ParamMeta *row : rows)
        if (row->branch == branch)
            return row;
    const bool branched = std::any_of(rows.begin(), rows.end(),
                                      [](const dev::ParamMeta *r) { return r->branch != 0; });
    if (!branched && branch >= 1 && static_cast<std::size_t>(branch) <= rows.size())
        return rows[static_cast<std::size_t>(branch) - 1];
    return nullptr;
}

const dev::ParamMeta *responseRow(const dev::Dictionary &dictionary, const std::string &mode,
                                  const dev::ParamMeta &setValue)
{
    const auto &responses = dictionary.monitor.forMode(mode).responses;
    const auto it = responses.find(setValue.name);
    return it == responses.end() ? nullptr : dictionary.find(it->second);
}

std::vector<const dev::ParamMeta *> recordedRows(const dev::Dictionary &dictionary,
                                                 const std::string &mode,
                                                 const dev::ParamMeta &setValue)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const std::string &name : dictionary.monitor.forMode(mode).channels)
        if (const dev::ParamMeta *row = dictionary.find(name))
            rows.push_back(row);
    if (const dev::ParamMeta *answer = responseRow(dictionary, mode, setValue);
        answer && std::find(rows.begin(), rows.end(), answer) == rows.end())
        rows.push_back(answer);
    return rows;
}

double setValueRaw(const dev::ParamMeta &setValue, double display)
{
    const double factor = setValue.scale.factor != 0 ? setValue.scale.factor : 1.0;
    return std::round(display / factor);
}

const dev::FaultRow *faultCheck(const dev::Dictionary &dictionary, const std::string &mode)
{
    const auto &fault = dictionary.monitor.forMode(mode).fault;
    return fault && dictionary.find(fault->row) ? &*fault : nullptr;
}

} // namespace vt::model
