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
      m_values(std::make_unique_for_overwrite<float[]>(static_cast<std::size_t>(m_capacity) *
                                                       static_cast<std::size_t>(m_channels.size())))
{
}

qint64 SampleStore::ringBytes(qsizetype channels, qsizetype capacity)
{
    return static_cast<qint64>(capacity) *
           static_cast<qint64>(sizeof(double) + static_cast<std::size_t>(channels) * sizeof(float));
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
    for (std::size_t c = 0; c < static_cast<std::size_t>(m_channels.size()); ++c) {
        const double v = c < values.size() ? values[c] : std::numeric_limits<double>::quiet_NaN();
        m_values[c * cap + slot] =
            std::isfinite(v) ? static_cast<float>(v) : std::numeric_limits<float>::quiet_NaN();
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
    int bucket = -1;
    double nextEdge = -std::numeric_limits<double>::infinity(); // first time of the next slice
    forEachSegment(
        m_head, static_cast<std::size_t>(m_capacity), i0, i1, [&](std::size_t p, std::size_t end) {
            for (; p < end; ++p) {
                const float v = values[p];
                if (std::isnan(v))
                    continue;
                const double t = m_times[p];
                const auto value = static_cast<double>(v);
                if (t >= nextEdge) {
                    const int b =
                        width > 0 ? std::min(buckets - 1, static_cast<int>((t - t0) / width)) : 0;
                    if (b != bucket) {
                        bucket = b;
                        nextEdge = b == buckets - 1 ? std::numeric_limits<double>::infinity()
                                                    : t0 + (b + 1) * width;
                        out.push_back({t, value, t, value});
                        continue;
                    }
                }
                MinMaxBucket &m = out.back();
                if (value < m.min) {
                    m.min = value;
                    m.tMin = t;
                }
                if (value > m.max) {
                    m.max = value;
                    m.tMax = t;
                }
            }
        });
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
