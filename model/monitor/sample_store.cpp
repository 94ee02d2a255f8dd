#include "sample_store.h"

#include "model/monitor/ring_segments.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

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
    ++m_clears;
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
    return firstRowNot(0, m_size, [t](double time) { return time < t; });
}

qsizetype SampleStore::upperBound(double t) const
{
    return firstRowNot(0, m_size, [t](double time) { return time <= t; });
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
