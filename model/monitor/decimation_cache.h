// DecimationCache: one plotted channel's min/max slices kept between redraws, so a live plot
// that follows the newest samples reads only the rows that arrived since its last redraw instead
// of the whole window (at the in-process simulator's 56 000 rows per second and module, a 10 s
// window is 560 000 rows per channel; 50 ms later 2 800 of them are new).
// The slices lie on a fixed grid of the time axis — slice k holds the rows with
// k·w <= t < (k + 1)·w, w = (t1 − t0) / buckets — so they stay valid as the window moves; the
// slices that left the window are dropped. A different width (zoom, resize) or channel, a
// clear() of the store, rows overwritten by the ring before they were read, or a range that
// starts before what is cached start again from the store (reading the whole range, once).
// Rows the ring overwrote after they were read leave the slices too: what the cache returns is
// always what the store holds.
// Each slice keeps its lowest and highest value and when each occurred (the first occurrence
// wins a tie): SampleStore::decimateOnGrid() makes them, MinMaxBucket::fold() adds newer rows.
// Owner: MonitorPlot, one per graph. GUI thread, like the store.
#pragma once

#include "model/monitor/sample_store.h"

#include <deque>
#include <vector>

namespace vt::model {

class DecimationCache
{
public:
    // The slices of `channel` of `store` that overlap [t0, t1] (at most buckets + 1: the grid's
    // first and last slice may reach beyond the range), in time order; slices without a value
    // are left out. Empty for a bad channel, buckets <= 0 or t1 <= t0.
    std::vector<MinMaxBucket> slices(const SampleStore &store, int channel, double t0, double t1,
                                     int buckets);
    // Forgets everything (the next call reads its range from the store).
    void reset();

    // What the last call did, for tests and the benchmark: rows read, and whether it started
    // again from the store.
    qsizetype lastRowsRead() const { return m_lastRowsRead; }
    bool lastRebuilt() const { return m_lastRebuilt; }

private:
    struct Slice
    {
        qint64 index; // k: the slice holds k·w <= t < (k + 1)·w
        MinMaxBucket extremes;
    };
    void start(const SampleStore &store, int channel, double width, qint64 firstIndex);
    void readNewRows(const SampleStore &store);
    qint64 indexOf(double t) const;

    const SampleStore *m_store = nullptr;
    int m_channel = -1;
    quint64 m_clears = 0;
    double m_width = 0;
    qint64 m_from = 0;     // every row with time >= m_from·w up to m_next has been read
    quint64 m_next = 0;    // number (SampleStore::appendedCount() counting) of the next row to read
    quint64 m_dropped = 0; // the store's droppedCount() when the slices last matched it
    std::deque<Slice> m_slices;
    qsizetype m_lastRowsRead = 0;
    bool m_lastRebuilt = false;
};

} // namespace vt::model
