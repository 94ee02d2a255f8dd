#include "test_recording.h"

namespace vt::model {

namespace {

double rate(const std::vector<double> &t)
{
    if (t.size() < 2 || !(t.back() > t.front()))
        return 0;
    return static_cast<double>(t.size() - 1) / (t.back() - t.front());
}

} // namespace

double TestRecording::updateRateHz() const
{
    return rate(setValue.t);
}

double TestRecording::sampleRateHz() const
{
    return channels.empty() ? 0 : rate(channels.front().t);
}

const Samples *TestRecording::channel(const dev::ParamMeta *row) const
{
    for (std::size_t i = 0; i < rows.size() && i < channels.size(); ++i)
        if (rows[i] == row)
            return &channels[i];
    return nullptr;
}

} // namespace vt::model
