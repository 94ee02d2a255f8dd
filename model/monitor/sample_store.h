// SampleStore: the live monitor's bounded ring of polled values — one shared
// timestamp per row, because the session polls a module's d-block in one request — with
// min/max decimation for the plot and time markers for the tuning journal's parameter writes.
// Owner: the monitor's session owner; GUI thread only (no locking; the session appends there).
//
// Memory is fixed at construction: 8 bytes (double time) + 4 bytes (float) per channel per row,
// plus each channel's summary of every kBlockRows rows (12 bytes), for decimateOnGrid(). The
// default (1 h at 200 Hz = 720 000 rows) with 5 channels: 720 000 × 28 B + 22 502 × 5 × 12 B = 21
// 510 120 B (20.5 MiB); markers add at most 1000 × (32 B + 256 UTF-16 chars) = 544 000 B (0.52
// MiB). The ring is allocated untouched (the system maps its pages on first write); makeResident()
// touches it all at once, so a monitoring run does not creep up by 28 B a poll for an hour.
// Values are floats: they come from 16-bit fieldbus words, and a float's 24-bit mantissa
// resolves more than that.
#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

class QIODevice;

namespace vt::model {

struct SampleChannel
{
    QString id;   // stable key: "d1.11"
    QString name; // for people: "actual value"
    QString unit; // "%", "bar"
    bool operator==(const SampleChannel &) const = default;
};

struct SampleMarker
{
    double t = 0; // seconds, on the samples' time axis
    QString text; // "C1.07 P gain 1.20 → 1.50"
    bool operator==(const SampleMarker &) const = default;
};

// One time slice of a decimated range: its lowest and highest value and when each occurred.
struct MinMaxBucket
{
    double tMin = 0;
    double min = 0;
    double tMax = 0;
    double max = 0;

    // A later row of the slice: it replaces an extreme only when strictly beyond it, so the
    // first occurrence wins a tie.
    void fold(double t, double value)
    {
        if (value < min) {
            min = value;
            tMin = t;
        }
        if (value > max) {
            max = value;
            tMax = t;
        }
    }
    // The extremes of later rows of the same slice, by the same rule.
    void fold(const MinMaxBucket &later)
    {
        if (later.min < min) {
            min = later.min;
            tMin = later.tMin;
        }
        if (later.max > max) {
            max = later.max;
            tMax = later.tMax;
        }
    }
};

// Limits of readCsv(), so a hostile or huge file cannot exhaust memory.
struct SampleCsvLimits
{
    qsizetype maxRows = 3600 * 200;
    qsizetype maxChannels = 64;
    qsizetype maxLineLength = 64 * 1024;
    qsizetype maxMarkers = 1000;
};

class SampleStore
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::SampleStore)
public:
    static constexpr qsizetype kDefaultCapacity = 3600 * 200; // 1 h at 200 Hz
    static constexpr qsizetype kDefaultMaxMarkers = 1000;
    static constexpr qsizetype kMaxMarkerText = 256; // characters; longer texts are cut
    // decimateOnGrid() folds whole blocks of this many rows from their summary (lowest and highest
    // value and where each is) instead of row by row: a redraw of 560 000 rows per channel in
    // 1000 pixels reads about 50 entries per pixel instead of 560.
    static constexpr qsizetype kBlockRows = 32;

    explicit SampleStore(QList<SampleChannel> channels, qsizetype capacity = kDefaultCapacity,
                         qsizetype maxMarkers = kDefaultMaxMarkers);

    // The ring's fixed footprint for a given shape, block summaries included (what memoryBytes()
    // reports without markers).
    static qint64 ringBytes(qsizetype channels, qsizetype capacity);
    // Everything the store holds: the ring, the channel list and the markers.
    qint64 memoryBytes() const;
    // Writes the rows not filled yet (their contents are never read), so the whole ring is
    // resident from now on instead of growing page by page as it fills. Idempotent; O(capacity)
    // the first time, O(1) after. Samples and markers are unchanged.
    void makeResident();
    bool isResident() const { return m_resident; }

    int channelCount() const { return static_cast<int>(m_channels.size()); }
    const QList<SampleChannel> &channels() const { return m_channels; }
    int channelIndex(const QString &id) const; // -1 if unknown

    qsizetype capacity() const { return m_capacity; }
    qsizetype size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    quint64 droppedCount() const { return m_dropped; } // rows overwritten by the ring
    // Rows appended since the last clear() (row i is number droppedCount() + i), and how many
    // clear()s there were: what DecimationCache needs to know which rows it has not read yet.
    quint64 appendedCount() const { return m_dropped + static_cast<quint64>(m_size); }
    quint64 clearCount() const { return m_clears; }

    // O(1). Times must not go backwards (equal is fine); a missing or non-finite value is stored
    // as NaN ("no value", skipped by decimation). Extra values are ignored. False for a bad time.
    bool append(double t, std::span<const double> values);
    void clear(); // samples and markers

    // Row i, 0 = oldest.
    double timeAt(qsizetype i) const { return m_times[physical(i)]; }
    double valueAt(int channel, qsizetype i) const;
    double firstTime() const
    {
        return m_size ? timeAt(0) : std::numeric_limits<double>::quiet_NaN();
    }
    double lastTime() const
    {
        return m_size ? timeAt(m_size - 1) : std::numeric_limits<double>::quiet_NaN();
    }
    // Binary search: first row with time >= t / first row with time > t (size() if none).
    qsizetype lowerBound(double t) const;
    qsizetype upperBound(double t) const;

    // Min/max slices on a fixed grid of the time axis (what DecimationCache keeps, and the plot
    // draws): from row `from` on, slice k holds the rows with k·width <= t < (k + 1)·width. Each
    // slice with a value (NaN-only slices are left out) is appended to `out` with its lowest and
    // highest value and when each occurred, and its k to `indices`, in time order. Every extreme
    // survives, so a single-sample spike stays visible. Whole blocks of kBlockRows rows inside
    // one slice are taken from their summary; the result is the same as reading every row (the
    // first occurrence wins a tie). Stops at the first row of a slice after `last` and returns
    // that row (size() when all were read).
    qsizetype decimateOnGrid(int channel, qsizetype from, double width, qint64 last,
                             std::vector<MinMaxBucket> &out, std::vector<qint64> &indices) const;
    // The buckets as a polyline for the plot: min and max of each slice in the order they
    // occurred (one point when they are the same sample).
    static void toPolyline(const std::vector<MinMaxBucket> &buckets, QList<double> &times,
                           QList<double> &values);
    // Every row of the range, undecimated (zoomed-in plots; the benchmark's baseline).
    qsizetype copyRange(int channel, double t0, double t1, QList<double> &times,
                        QList<double> &values) const;

    // Markers are kept in time order, the oldest dropped beyond maxMarkers; texts are cut to
    // kMaxMarkerText characters so the markers' memory has a bound, too.
    void addMarker(double t, const QString &text);
    const std::deque<SampleMarker> &markers() const { return m_markers; }
    QList<SampleMarker> markersIn(double t0, double t1) const;

    // CSV with '#' header lines naming the channels, one row per sample (empty cell = NaN) and
    // one row per marker (empty values, text in the last column). Separator and decimal sign
    // follow the UI language (German ';' and ',', else ',' and '.'); the first lines state them,
    // and numbers round-trip exactly. False (and *error) on a write error.
    bool writeCsv(QIODevice &out, double t0, double t1, QString *error = nullptr) const;
    bool writeCsv(QIODevice &out, QString *error = nullptr) const;
    // Reads what writeCsv() wrote into a store with capacity = the rows read (at least 1).
    static std::optional<SampleStore> readCsv(QIODevice &in, QString *error = nullptr,
                                              const SampleCsvLimits &limits = {});

private:
    // The lowest and highest non-NaN value of one block of kBlockRows rows and their offsets in
    // the block (-1: no value yet). Block k holds the rows appended as numbers k·kBlockRows ..
    // k·kBlockRows + kBlockRows − 1 since the last clear(); row number n sits in slot
    // n % capacity, so the ring of summaries, numbered k % blockSlots, follows the ring of rows.
    struct BlockSummary
    {
        float min;
        float max;
        qint16 minAt;
        qint16 maxAt;
    };
    // decimateOnGrid()'s slicing (sample_store_slices.cpp): rows
    // [i0, i1) in time order into slice sliceOf(t) (non-decreasing in t), which ends before
    // edgeAfter(slice); a row that would open a slice after `last` ends the scan, and its index
    // is returned (else i1). `dense`: whole blocks inside a slice are taken from their summaries.
    template<typename SliceOf, typename EdgeAfter>
    qsizetype scan(int channel, qsizetype i0, qsizetype i1, qint64 last, bool dense,
                   SliceOf sliceOf, EdgeAfter edgeAfter, std::vector<MinMaxBucket> &out,
                   std::vector<qint64> *indices) const;
    // Binary search: the first row in [lo, hi) whose time is not before(time) (size() order).
    template<typename Before> qsizetype firstRowNot(qsizetype lo, qsizetype hi, Before before) const
    {
        while (lo < hi) {
            const qsizetype mid = lo + (hi - lo) / 2;
            if (before(timeAt(mid)))
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    }
    static qsizetype blockSlots(qsizetype capacity) { return capacity / kBlockRows + 2; }
    BlockSummary *summaries(int channel) const
    {
        return m_blocks.get() +
               static_cast<std::size_t>(channel) * static_cast<std::size_t>(m_blockSlots);
    }
    // Row number (counted since clear(), never wrapping) of row i.
    quint64 rowNumber(qsizetype i) const { return m_dropped + static_cast<quint64>(i); }

    std::size_t physical(qsizetype i) const // 0 <= i <= capacity: no division needed
    {
        const std::size_t p = m_head + static_cast<std::size_t>(i);
        const auto cap = static_cast<std::size_t>(m_capacity);
        return p < cap ? p : p - cap;
    }
    const float *column(int channel) const
    {
        return m_values.get() +
               static_cast<std::size_t>(channel) * static_cast<std::size_t>(m_capacity);
    }

    QList<SampleChannel> m_channels;
    qsizetype m_capacity;
    qsizetype m_maxMarkers;
    // Column-major: channel c's ring is m_values[c * capacity, (c + 1) * capacity), so decimating
    // one channel scans contiguous memory. Allocated once, never resized.
    std::unique_ptr<double[]> m_times;
    std::unique_ptr<float[]> m_values;
    qsizetype m_blockSlots;
    std::unique_ptr<BlockSummary[]> m_blocks; // channel-major like m_values
    std::size_t m_head = 0;                   // physical index of row 0
    qsizetype m_size = 0;
    quint64 m_dropped = 0;
    quint64 m_clears = 0;
    bool m_resident = false;
    std::deque<SampleMarker> m_markers;
};

} // namespace vt::model
