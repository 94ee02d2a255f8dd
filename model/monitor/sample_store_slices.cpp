// SampleStore's min/max slicing: decimateOnGrid() (slices on a fixed grid of the time axis, for
// DecimationCache) through scan().
#include "model/monitor/ring_segments.h"
#include "sample_store.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

template<typename SliceOf, typename EdgeAfter>
qsizetype SampleStore::scan(int channel, qsizetype i0, qsizetype i1, qint64 last, bool dense,
                            SliceOf sliceOf, EdgeAfter edgeAfter, std::vector<MinMaxBucket> &out,
                            std::vector<qint64> *indices) const
{
    const float *values = column(channel);
    const auto cap = static_cast<std::size_t>(m_capacity);
    qint64 slice = std::numeric_limits<qint64>::min();
    double nextEdge = -std::numeric_limits<double>::infinity(); // first time of the next slice
    // Row by row: the first row of a slice opens it, later ones fold into it
    // (MinMaxBucket::fold: ties keep the first occurrence).
    enum class Row { Folded, Opened, Beyond };
    const auto row = [&](double t, float v) {
        if (std::isnan(v))
            return Row::Folded;
        const auto value = static_cast<double>(v);
        if (t >= nextEdge) {
            const qint64 k = sliceOf(t);
            if (k != slice) {
                if (k > last)
                    return Row::Beyond;
                slice = k;
                nextEdge = edgeAfter(k);
                out.push_back({t, value, t, value});
                if (indices)
                    indices->push_back(k);
                return Row::Opened;
            }
        }
        out.back().fold(t, value);
        return Row::Folded;
    };
    if (!dense) { // a few blocks per slice at most: every row
        std::size_t p = physical(i0);
        for (qsizetype i = i0; i < i1; ++i) {
            if (row(m_times[p], values[p]) == Row::Beyond)
                return i;
            p = p + 1 == cap ? 0 : p + 1;
        }
        return i1;
    }

    // Dense: once a row opens a slice, every row before the slice's end (found by galloping
    // from there) folds into it, so whole blocks in between are taken from their summaries (the
    // same extremes, in the same order); only the rows before the first and after the last whole
    // block are read. Positions advance by addition, and a block's extreme's time is read only
    // when it is a new extreme of the slice: on a large ring the reads that miss the cache, not
    // the comparisons, are what a redraw costs (so this is MinMaxBucket::fold with the time
    // read late).
    const BlockSummary *blocks = summaries(channel);
    const auto blockCount = static_cast<std::size_t>(m_blockSlots);
    const auto wrap = [cap](std::size_t p) { return p < cap ? p : p - cap; };
    const auto foldRows = [&](qsizetype from, qsizetype to) {
        forEachSegment(m_head, cap, from, to, [&](std::size_t p, std::size_t end) {
            for (; p < end; ++p)
                if (!std::isnan(values[p]))
                    out.back().fold(m_times[p], static_cast<double>(values[p]));
        });
    };
    const auto firstAtOrAfter = [this](double t, qsizetype from, qsizetype to) {
        qsizetype lo = from;
        qsizetype hi = from;
        for (qsizetype step = 1; hi < to && timeAt(hi) < t; step *= 2) {
            lo = hi + 1;
            hi += step;
        }
        return firstRowNot(lo, std::min(hi, to), [t](double time) { return time < t; });
    };
    for (qsizetype i = i0; i < i1;) {
        const std::size_t p = physical(i);
        const Row r = row(m_times[p], values[p]);
        if (r == Row::Beyond)
            return i;
        ++i;
        if (r == Row::Folded)
            continue;
        const qsizetype end = std::isinf(nextEdge) ? i1 : firstAtOrAfter(nextEdge, i, i1);
        const auto intoBlock = static_cast<qsizetype>(rowNumber(i) % kBlockRows);
        qsizetype block = intoBlock ? i + kBlockRows - intoBlock : i;
        foldRows(i, std::min(block, end));
        if (block + kBlockRows <= end) {
            MinMaxBucket &m = out.back();
            std::size_t first = physical(block);
            auto k = static_cast<std::size_t>(rowNumber(block) / kBlockRows % blockCount);
            for (; block + kBlockRows <= end; block += kBlockRows) {
                const BlockSummary &s = blocks[k];
                if (s.minAt >= 0) { // else: no value in the block
                    if (static_cast<double>(s.min) < m.min) {
                        m.min = static_cast<double>(s.min);
                        m.tMin = m_times[wrap(first + static_cast<std::size_t>(s.minAt))];
                    }
                    if (static_cast<double>(s.max) > m.max) {
                        m.max = static_cast<double>(s.max);
                        m.tMax = m_times[wrap(first + static_cast<std::size_t>(s.maxAt))];
                    }
                }
                first = wrap(first + kBlockRows);
                k = k + 1 == blockCount ? 0 : k + 1;
            }
        }
        foldRows(std::max(block, i), end);
        i = end;
    }
    return i1;
}

qsizetype SampleStore::decimateOnGrid(int channel, qsizetype from, double width, qint64 last,
                                      std::vector<MinMaxBucket> &out,
                                      std::vector<qint64> &indices) const
{
    if (channel < 0 || channel >= channelCount() || !(width > 0) || from < 0 || from >= m_size)
        return std::clamp<qsizetype>(from, 0, m_size);
    const auto sliceOf = [width](double t) { // clamped: a time far from 0 in tiny slices
        return static_cast<qint64>(std::clamp(std::floor(t / width), -9e18, 9e18));
    };
    const qint64 slices = std::max<qint64>(1, last - sliceOf(timeAt(from)) + 1);
    return scan(
        channel, from, m_size, last, (m_size - from) / slices >= 4 * kBlockRows, sliceOf,
        [width](qint64 k) { return static_cast<double>(k + 1) * width; }, out, &indices);
}

void SampleStore::toPolyline(const std::vector<MinMaxBucket> &buckets, QList<double> &times,
                             QList<double> &values)
{
    times.clear();
    values.clear();
    times.reserve(static_cast<qsizetype>(buckets.size() * 2));
    values.reserve(static_cast<qsizetype>(buckets.size() * 2));
    for (const MinMaxBucket &b : buckets) {
        const bool minFirst = b.tMin <= b.tMax;
        times.append(minFirst ? b.tMin : b.tMax);
        values.append(minFirst ? b.min : b.max);
        if (b.tMin == b.tMax && b.min == b.max)
            continue;
        times.append(minFirst ? b.tMax : b.tMin);
        values.append(minFirst ? b.max : b.min);
    }
}

} // namespace vt::model
