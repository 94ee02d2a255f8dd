// Shared by the SampleStore and DecimationCache tests: channel lists for a store, and
// expectSameBuckets — two decimations agree bucket by bucket (extremes and when they occurred).
#pragma once

#include "model/monitor/sample_store.h"

#include <gtest/gtest.h>
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
