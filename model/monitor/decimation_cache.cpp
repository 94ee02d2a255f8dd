#include "decimation_cache.h"

#include <algorithm>
#include <cmath>

namespace vt::model {

qint64 DecimationCache::indexOf(double t) const
{
    return static_cast<qint64>(std::clamp(std::floor(t / m_width), -9e18, 9e18));
}

void DecimationCache::reset()
{
    m_store = nullptr;
    m_channel = -1;
    m_width = 0;
    m_from = 0;
    m_next = 0;
    m_dropped = 0;
    m_slices.clear();
}

void DecimationCache::start(const SampleStore &store, int channel, double width, qint64 firstIndex)
{
    m_store = &store;
    m_channel = channel;
    m_clears = store.clearCount();
    m_width = width;
    m_from = firstIndex;
    m_slices.clear();
    qsizetype i = store.lowerBound(static_cast<double>(firstIndex) * width);
    while (i > 0 && indexOf(store.timeAt(i - 1)) >= firstIndex)
        --i; // rows just below the edge that the division still puts into the first slice
    m_next = store.droppedCount() + static_cast<quint64>(i);
    m_dropped = store.droppedCount();
    m_lastRebuilt = true;
}

std::vector<MinMaxBucket> DecimationCache::slices(const SampleStore &store, int channel, double t0,
                                                  double t1, int buckets)
{
    m_lastRowsRead = 0;
    m_lastRebuilt = false;
    std::vector<MinMaxBucket> out;
    if (channel < 0 || channel >= store.channelCount() || buckets <= 0 || !(t1 > t0) ||
        !std::isfinite(t0) || !std::isfinite(t1))
        return out;
    // A view that follows the samples moves t0 and t1 together; their difference then varies in
    // its last bits, which must not count as a new width.
    const double width = (t1 - t0) / buckets;
    const bool sameWidth = m_width > 0 && std::abs(width - m_width) <= 1e-9 * m_width;
    const double w = sameWidth ? m_width : width;
    const auto index = [w](double t) {
        return static_cast<qint64>(std::clamp(std::floor(t / w), -9e18, 9e18));
    };
    const qint64 first = index(t0);
    const qint64 last = index(t1);
    if (&store != m_store || channel != m_channel || store.clearCount() != m_clears || !sameWidth ||
        first < m_from || m_next < store.droppedCount() || m_next > store.appendedCount())
        start(store, channel, w, first);

    const auto from = static_cast<qsizetype>(m_next - store.droppedCount());
    std::vector<MinMaxBucket> read;
    std::vector<qint64> indices;
    const qsizetype stop = store.decimateOnGrid(channel, from, m_width, last, read, indices);
    m_lastRowsRead = stop - from;
    m_next = store.droppedCount() + static_cast<quint64>(stop);
    for (std::size_t j = 0; j < read.size(); ++j) {
        if (m_slices.empty() || m_slices.back().index != indices[j]) {
            m_slices.push_back({indices[j], read[j]});
            continue;
        }
        // The slice's newest rows: the rows read before came first, so they win a tie.
        m_slices.back().extremes.fold(read[j]);
    }
    while (!m_slices.empty() && m_slices.front().index < first)
        m_slices.pop_front();
    m_from = std::max(m_from, first);
    if (store.droppedCount() != m_dropped) {
        // The ring overwrote rows: slices older than its oldest row go, and the slice that
        // holds it is read again from what the store still has of it.
        m_dropped = store.droppedCount();
        const qint64 oldest = index(store.firstTime());
        while (!m_slices.empty() && m_slices.front().index < oldest)
            m_slices.pop_front();
        if (!m_slices.empty() && m_slices.front().index == oldest) {
            read.clear();
            indices.clear();
            store.decimateOnGrid(channel, 0, m_width, oldest, read, indices);
            if (read.empty() || indices.front() != oldest)
                m_slices.pop_front();
            else
                m_slices.front().extremes = read.front();
        }
    }
    for (const Slice &slice : m_slices) {
        if (slice.index > last)
            break;
        out.push_back(slice.extremes);
    }
    return out;
}

} // namespace vt::model
