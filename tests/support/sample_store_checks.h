// Shared by the SampleStore and DecimationCache tests: channel lists for a store, the slices of
// a grid computed the slow way, and expectSameBuckets — two decimations agree bucket by bucket
// (extremes and when they occurred).
#pragma once

#include "model/monitor/sample_store.h"

#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <vector>

namespace vt::test {

// n channels "d1.7", "d1.8", … named "value 0", "value 1", … in %.
inline QList<model::SampleChannel> storeChannels(int n)
{
    QList<model::SampleChannel> out;
    for (int i = 0; i < n; ++i)
        out.append({QStringLiteral("d1.%1").arg(7 + i), QStringLiteral("value %1").arg(i),
                    QStringLiteral("%")});
    return out;
}

// The slow way, for the references: a later row replaces an extreme only when strictly beyond
// it (the first occurrence wins a tie).
inline void foldRow(model::MinMaxBucket &m, double t, double v)
{
    if (v < m.min) {
        m.min = v;
        m.tMin = t;
    }
    if (v > m.max) {
        m.max = v;
        m.tMax = t;
    }
}

// Every row of the store, grouped by floor(t / width) for the slices first..last (the grid of
// SampleStore::decimateOnGrid and DecimationCache), NaN skipped, the first occurrence winning a
// tie.
inline std::vector<model::MinMaxBucket> gridByEveryRow(const model::SampleStore &s, int channel,
                                                       double width, qint64 first, qint64 last)
{
    std::map<qint64, model::MinMaxBucket> slices;
    for (qsizetype i = 0; i < s.size(); ++i) {
        const double t = s.timeAt(i);
        const double v = s.valueAt(channel, i);
        const auto k = static_cast<qint64>(std::floor(t / width));
        if (std::isnan(v) || k < first || k > last)
            continue;
        const auto [at, added] = slices.try_emplace(k, model::MinMaxBucket{t, v, t, v});
        if (!added)
            foldRow(at->second, t, v);
    }
    std::vector<model::MinMaxBucket> out;
    for (const auto &[k, b] : slices)
        out.push_back(b);
    return out;
}

inline void expectSameBuckets(const std::vector<model::MinMaxBucket> &got,
                              const std::vector<model::MinMaxBucket> &want)
{
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].min, want[i].min) << "bucket " << i;
        EXPECT_EQ(got[i].tMin, want[i].tMin) << "bucket " << i;
        EXPECT_EQ(got[i].max, want[i].max) << "bucket " << i;
        EXPECT_EQ(got[i].tMax, want[i].tMax) << "bucket " << i;
    }
}

} // namespace vt::test
