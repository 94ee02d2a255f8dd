#include "sample_store.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

namespace {

// Calls fn(firstPhysical, lastPhysical) for the (at most two) contiguous pieces of rows [i0, i1).
template<typename Fn>
void forEachSegment(std::size_t head, std::size_t capacity, qsizetype i0, qsizetype i1, Fn fn)
{
    if (i0 >= i1)
        return;
    const std::size_t p0 = (head + static_cast<std::size_t>(i0)) % capacity;
    const auto n = static_cast<std::size_t>(i1 - i0);
    const std::size_t first = std::min(n, capacity - p0);
    fn(p0, p0 + first);
    if (first < n)
        fn(std::size_t{0}, n - first);
}

} // namespace

SampleStore::SampleStore(QList<SampleChannel> channels, qsizetype capacity, qsizetype maxMarkers)
    : m_channels(std::move(channels)), m_capacity(qMax<qsizetype>(1, capacity)),
      m_maxMarkers(qMax<qsizetype>(0, maxMarkers)),
      // for_overwrite: no zero fill, so pages are only touched as the ring fills.
      m_times(std::make_unique_for_overwrite<double[]>(static_cast<std::size_t>(m_capacity))),
      m_values(std::make_unique_for_overwrite<float[]>(
          static_cast<std::size_t>(m_capacity) * static_cast<std::size_t>(m_channels.size()))),
      m_blockSlots(blockSlots(m_capacity)),
      m_blocks(std::make_unique_for_overwrite<BlockSummary[]>(
          static_cast<std::size_t>(m_blockSlots) * static_cast<std::size_t>(m_channels.size())))
{
}

qint64 SampleStore::ringBytes(qsizetype channels, qsizetype capacity)
{
    return static_cast<qint64>(capacity) *
               static_cast<qint64>(sizeof(double) +
                                   static_cast<std::size_t>(channels) * sizeof(float)) +
           static_cast<qint64>(blockSlots(capacity)) * channels *
               static_cast<qint64>(sizeof(BlockSummary));
}

qint64 SampleStore::memoryBytes() const
{
    qint64 bytes =
        static_cast<qint64>(sizeof(SampleStore)) + ringBytes(m_channels.size(), m_capacity);
    for (const SampleChannel &c : m_channels)
        bytes += static_cast<qint64>(sizeof(SampleChannel)) +
                 (c.id.size() + c.name.size() + c.unit.size()) * static_cast<qint64>(sizeof(QChar));
    for (const SampleMarker &m : m_markers)
        bytes += static_cast<qint64>(sizeof(SampleMarker)) +
                 m.text.size() * static_cast<qint64>(sizeof(QChar));
    return bytes;
}

void SampleStore::makeResident()
{
    if (m_resident)
        return;
    m_resident = true;
    const auto cap = static_cast<std::size_t>(m_capacity);
    // The physical slots of rows [size, capacity): where the next appends will write.
    forEachSegment(m_head, cap, m_size, m_capacity, [&](std::size_t p, std::size_t end) {
        std::fill(m_times.get() + p, m_times.get() + end, 0.0);
        for (std::size_t c = 0; c < static_cast<std::size_t>(m_channels.size()); ++c)
            std::fill(m_values.get() + c * cap + p, m_values.get() + c * cap + end,
                      std::numeric_limits<float>::quiet_NaN());
    });
    // The summaries of blocks no row is in yet (the next ones the appends will start), too.
    const quint64 blockCount = static_cast<quint64>(m_blockSlots);
    const quint64 firstFree = m_size ? (rowNumber(m_size - 1) / kBlockRows + 1) : 0;
    const quint64 inUse = m_size ? firstFree - rowNumber(0) / kBlockRows : 0;
    for (quint64 k = firstFree; k < firstFree + blockCount - inUse; ++k) {
        for (int c = 0; c < channelCount(); ++c)
            summaries(c)[k % blockCount] = BlockSummary{0, 0, -1, -1};
    }
}

int SampleStore::channelIndex(const QString &id) const
{
    for (int i = 0; i < channelCount(); ++i)
        if (m_channels[i].id == id)
            return i;
    return -1;
}

bool SampleStore::append(double t, std::span<const double> values)
{
    if (!std::isfinite(t) || (m_size > 0 && t < lastTime()))
        return false;
    const quint64 number = rowNumber(m_size); // this row's number since clear()
    std::size_t slot = 0;
    if (m_size < m_capacity) {
        slot = physical(m_size);
        ++m_size;
    } else {
        slot = m_head; // overwrite the oldest row
        m_head = (m_head + 1) % static_cast<std::size_t>(m_capacity);
        ++m_dropped;
    }
    m_times[slot] = t;
    const auto cap = static_cast<std::size_t>(m_capacity);
    const auto block = static_cast<std::size_t>(number / kBlockRows % quint64(m_blockSlots));
    const auto offset = static_cast<qint16>(number % kBlockRows);
    for (std::size_t c = 0; c < static_cast<std::size_t>(m_channels.size()); ++c) {
        const double v = c < values.size() ? values[c] : std::numeric_limits<double>::quiet_NaN();
        const float stored =
            std::isfinite(v) ? static_cast<float>(v) : std::numeric_limits<float>::quiet_NaN();
        m_values[c * cap + slot] = stored;
        BlockSummary &summary = summaries(static_cast<int>(c))[block];
        if (offset == 0)
            summary = {0, 0, -1, -1};
        if (std::isnan(stored))
            continue;
        if (summary.minAt < 0 || stored < summary.min) {
            summary.min = stored;
            summary.minAt = offset;
        }
        if (summary.maxAt < 0 || stored > summary.max) {
            summary.max = stored;
            summary.maxAt = offset;
        }
    }
    return true;
}

void SampleStore::clear()
{
    m_head = 0;
    m_size = 0;
    m_dropped = 0;
    m_markers.clear();
}

double SampleStore::valueAt(int channel, qsizetype i) const
{
    if (channel < 0 || channel >= channelCount() || i < 0 || i >= m_size)
        return std::numeric_limits<double>::quiet_NaN();
    return static_cast<double>(column(channel)[physical(i)]);
}

qsizetype SampleStore::lowerBound(double t) const
{
    qsizetype lo = 0;
    qsizetype hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

qsizetype SampleStore::upperBound(double t) const
{
    qsizetype lo = 0;
    qsizetype hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) <= t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::vector<MinMaxBucket> SampleStore::decimate(int channel, double t0, double t1,
                                                int buckets) const
{
    std::vector<MinMaxBucket> out;
    if (channel < 0 || channel >= channelCount() || buckets <= 0 || !(t0 <= t1))
        return out;
    const qsizetype i0 = lowerBound(t0);
    const qsizetype i1 = upperBound(t1);
    const double width = (t1 - t0) / buckets;
    const float *values = column(channel);
    const auto cap = static_cast<std::size_t>(m_capacity);
    int bucket = -1;
    double nextEdge = -std::numeric_limits<double>::infinity(); // first time of the next slice
    // Row by row: the first row of a slice opens it, later ones fold into it. Ties keep the
    // first occurrence.
    const auto fold = [&out](double t, double value) {
        MinMaxBucket &m = out.back();
        if (value < m.min) {
            m.min = value;
            m.tMin = t;
        }
        if (value > m.max) {
            m.max = value;
            m.tMax = t;
        }
    };
    const auto row = [&](double t, float v) { // false: the row opened a new slice
        if (std::isnan(v))
            return true;
        const auto value = static_cast<double>(v);
        if (t >= nextEdge) {
            const int b = width > 0 ? std::min(buckets - 1, static_cast<int>((t - t0) / width)) : 0;
            if (b != bucket) {
                bucket = b;
                nextEdge = b == buckets - 1 ? std::numeric_limits<double>::infinity()
                                            : t0 + (b + 1) * width;
                out.push_back({t, value, t, value});
                return false;
            }
        }
        fold(t, value);
        return true;
    };
    if ((i1 - i0) / buckets < 4 * kBlockRows) { // sparse: a few blocks per slice at most
        forEachSegment(m_head, cap, i0, i1, [&](std::size_t p, std::size_t end) {
            for (; p < end; ++p)
                row(m_times[p], values[p]);
        });
        return out;
    }

    // Dense: once a row opens a slice, every row before the slice's end (found by galloping
    // from there) folds into it, so whole blocks in between are taken from their summaries (the
    // same extremes, in the same order); only the rows before the first and after the last whole
    // block are read. Positions advance by addition, and a block's extreme's time is read only
    // when it is a new extreme of the slice: on a large ring the reads that miss the cache, not
    // the comparisons, are what a redraw costs.
    const BlockSummary *blocks = summaries(channel);
    const auto blockCount = static_cast<std::size_t>(m_blockSlots);
    const auto wrap = [cap](std::size_t p) { return p < cap ? p : p - cap; };
    const auto foldRows = [&](qsizetype from, qsizetype to) {
        forEachSegment(m_head, cap, from, to, [&](std::size_t p, std::size_t end) {
            for (; p < end; ++p)
                if (!std::isnan(values[p]))
                    fold(m_times[p], static_cast<double>(values[p]));
        });
    };
    const auto firstAtOrAfter = [this](double t, qsizetype from, qsizetype to) {
        qsizetype lo = from;
        qsizetype hi = from;
        for (qsizetype step = 1; hi < to && timeAt(hi) < t; step *= 2) {
            lo = hi + 1;
            hi += step;
        }
        hi = std::min(hi, to);
        while (lo < hi) {
            const qsizetype mid = lo + (hi - lo) / 2;
            if (timeAt(mid) < t)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    };
    for (qsizetype i = i0; i < i1;) {
        const std::size_t p = physical(i++);
        if (row(m_times[p], values[p]))
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
                if (s.minAt >= 0) {
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
    return out;
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

qsizetype SampleStore::copyRange(int channel, double t0, double t1, QList<double> &times,
                                 QList<double> &values) const
{
    times.clear();
    values.clear();
    if (channel < 0 || channel >= channelCount() || !(t0 <= t1))
        return 0;
    const qsizetype i0 = lowerBound(t0);
    const qsizetype i1 = upperBound(t1);
    times.reserve(i1 - i0);
    values.reserve(i1 - i0);
    const float *column = this->column(channel);
    forEachSegment(m_head, static_cast<std::size_t>(m_capacity), i0, i1,
                   [&](std::size_t p, std::size_t end) {
                       for (; p < end; ++p) {
                           times.append(m_times[p]);
                           values.append(static_cast<double>(column[p]));
                       }
                   });
    return times.size();
}

void SampleStore::addMarker(double t, const QString &text)
{
    if (m_maxMarkers == 0 || !std::isfinite(t))
        return;
    const auto at = std::upper_bound(m_markers.begin(), m_markers.end(), t,
                                     [](double time, const SampleMarker &m) { return time < m.t; });
    m_markers.insert(at, SampleMarker{t, text.left(kMaxMarkerText)});
    while (static_cast<qsizetype>(m_markers.size()) > m_maxMarkers)
        m_markers.pop_front();
}

QList<SampleMarker> SampleStore::markersIn(double t0, double t1) const
{
    QList<SampleMarker> out;
    for (const SampleMarker &m : m_markers)
        if (m.t >= t0 && m.t <= t1)
            out.append(m);
    return out;
}

} // namespace vt::model
