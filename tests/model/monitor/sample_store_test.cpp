// SampleStore: issue #8 — a ring sized for ≥ 1 h at 200 Hz for 5 channels with a stated,
// fixed memory footprint, and min/max decimation to about one pair per pixel.
#include "model/monitor/decimation_cache.h"
#include "model/monitor/sample_store.h"
#include "resident_memory.h"
#include "sample_store_checks.h"

#include <QBuffer>
#include <QLocale>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <malloc.h>
#include <random>

using vt::model::DecimationCache;
using vt::model::MinMaxBucket;
using vt::model::SampleChannel;
using vt::model::SampleCsvLimits;
using vt::model::SampleMarker;
using vt::model::SampleStore;

namespace {

QList<SampleChannel> channels(int n)
{
    return vt::test::storeChannels(n);
}

void appendRow(SampleStore &s, double t, std::initializer_list<double> values)
{
    ASSERT_TRUE(s.append(t, std::span<const double>(values.begin(), values.size())));
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

TEST(SampleStore, DefaultHoldsOneHourAt200HzWithAStatedFootprint)
{
    SampleStore s(channels(5));
    EXPECT_EQ(s.capacity(), 720'000);
    // 28 B per row, and 12 B per channel for every 32 rows' summary (22 500 blocks + 2)
    EXPECT_EQ(SampleStore::ringBytes(5, 720'000), 720'000 * 28 + 22'502 * 5 * 12);
    EXPECT_GE(s.memoryBytes(), 21'510'120);
    EXPECT_LT(s.memoryBytes(), 21'520'000);
}

TEST(SampleStore, MemoryStaysFixedAfterTwoHoursAt200Hz)
{
    SampleStore s(channels(5));
    const qint64 before = s.memoryBytes();
    const qsizetype rows = 2 * 3600 * 200;
    double values[5] = {};
    for (qsizetype i = 0; i < rows; ++i) {
        const double t = static_cast<double>(i) / 200.0;
        for (int c = 0; c < 5; ++c)
            values[c] = t * (c + 1);
        ASSERT_TRUE(s.append(t, values));
    }
    EXPECT_EQ(s.memoryBytes(), before);
    EXPECT_EQ(s.size(), s.capacity());
    EXPECT_EQ(s.droppedCount(), quint64(rows - s.capacity()));
    EXPECT_DOUBLE_EQ(s.firstTime(), 3600.0); // the newest hour
    EXPECT_DOUBLE_EQ(s.lastTime(), static_cast<double>(rows - 1) / 200.0);
    EXPECT_FLOAT_EQ(static_cast<float>(s.valueAt(4, 0)), static_cast<float>(3600.0 * 5));
}

TEST(SampleStore, WrapKeepsTheNewestRows)
{
    SampleStore s(channels(2), 10);
    for (int i = 0; i < 25; ++i)
        appendRow(s, i, {double(i), -double(i)});
    EXPECT_EQ(s.size(), 10);
    EXPECT_EQ(s.droppedCount(), 15u);
    for (qsizetype i = 0; i < 10; ++i) {
        EXPECT_EQ(s.timeAt(i), double(15 + i));
        EXPECT_EQ(s.valueAt(0, i), double(15 + i));
        EXPECT_EQ(s.valueAt(1, i), -double(15 + i));
    }
    EXPECT_TRUE(std::isnan(s.valueAt(2, 0)));  // no such channel
    EXPECT_TRUE(std::isnan(s.valueAt(0, 10))); // no such row
}

TEST(SampleStore, AppendRejectsTimeGoingBackwardsAndFillsMissingValues)
{
    SampleStore s(channels(3), 10);
    appendRow(s, 1.0, {1, 2, 3});
    appendRow(s, 1.0, {4}); // same time is fine; missing values are NaN
    EXPECT_FALSE(s.append(0.5, std::vector<double>{1, 2, 3}));
    EXPECT_FALSE(s.append(kNaN, std::vector<double>{1, 2, 3}));
    EXPECT_EQ(s.size(), 2);
    EXPECT_EQ(s.valueAt(0, 1), 4.0);
    EXPECT_TRUE(std::isnan(s.valueAt(1, 1)));
    EXPECT_TRUE(std::isnan(s.valueAt(2, 1)));
    s.clear();
    EXPECT_TRUE(s.isEmpty());
    EXPECT_TRUE(s.append(0.5, std::vector<double>{1, 2, 3})); // a cleared store starts over
}

TEST(SampleStore, TimeQueriesAtTheRingEdges)
{
    SampleStore s(channels(1), 8);
    for (int i = 0; i < 13; ++i) // rows 5..12 kept; physically wrapped after row 7
        appendRow(s, i * 0.5, {double(i)});
    ASSERT_EQ(s.size(), 8);
    EXPECT_EQ(s.lowerBound(-1.0), 0);
    EXPECT_EQ(s.lowerBound(2.5), 0); // exactly the oldest
    EXPECT_EQ(s.upperBound(2.5), 1);
    EXPECT_EQ(s.lowerBound(2.6), 1);
    EXPECT_EQ(s.lowerBound(6.0), 7); // exactly the newest
    EXPECT_EQ(s.upperBound(6.0), 8);
    EXPECT_EQ(s.lowerBound(99.0), 8);
    for (qsizetype i = 0; i < 8; ++i) { // across the physical wrap
        EXPECT_EQ(s.lowerBound(s.timeAt(i)), i);
        EXPECT_EQ(s.upperBound(s.timeAt(i)), i + 1);
    }
    QList<double> t, v;
    EXPECT_EQ(s.copyRange(0, 3.0, 4.5, t, v), 4);
    EXPECT_EQ(t, (QList<double>{3.0, 3.5, 4.0, 4.5}));
    EXPECT_EQ(v, (QList<double>{6, 7, 8, 9}));
    EXPECT_EQ(s.copyRange(0, 7.0, 9.0, t, v), 0);
    EXPECT_TRUE(DecimationCache().slices(s, 0, 7.0, 9.0, 10).empty());
    EXPECT_TRUE(DecimationCache().slices(s, 0, 3.0, 2.0, 10).empty());
}

namespace {

// A redraw from scratch of [t0, t1] in `buckets` slices (what the plot draws after a zoom:
// DecimationCache over SampleStore::decimateOnGrid), against every row of the slices of that
// grid, computed the slow way.
std::vector<MinMaxBucket> expectMatchesBruteForce(const SampleStore &s, double t0, double t1,
                                                  int buckets, int channel = 0)
{
    const std::vector<MinMaxBucket> got = DecimationCache().slices(s, channel, t0, t1, buckets);
    if (!(t1 > t0)) {
        EXPECT_TRUE(got.empty());
        return got;
    }
    const double width = (t1 - t0) / buckets;
    vt::test::expectSameBuckets(
        got,
        vt::test::gridByEveryRow(s, channel, width, static_cast<qint64>(std::floor(t0 / width)),
                                 static_cast<qint64>(std::floor(t1 / width))));
    return got;
}

} // namespace

TEST(SampleStore, DecimationKeepsEveryExtremeAndASingleSpike)
{
    SampleStore s(channels(1), 100'000);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.1);
    for (int i = 0; i < 150'000; ++i) { // wraps: rows 50 000..149 999 stay
        const double t = i * 0.005;
        double v = std::sin(t) + noise(rng);
        if (i == 123'457)
            v = 1000.0; // one-sample spike
        if (i == 98'765)
            v = -1000.0; // one-sample dip
        if (i % 1000 == 3)
            v = kNaN; // missing values are skipped
        appendRow(s, t, {v});
    }
    const std::vector<MinMaxBucket> buckets =
        expectMatchesBruteForce(s, s.firstTime(), s.lastTime(), 800);
    EXPECT_GE(buckets.size(), 800u); // the grid's first slice may start before the first row
    EXPECT_LE(buckets.size(), 801u);
    double max = -1e9, min = 1e9, tMax = 0, tMin = 0;
    for (const MinMaxBucket &b : buckets) {
        EXPECT_LE(b.tMin, s.lastTime());
        if (b.max > max) {
            max = b.max;
            tMax = b.tMax;
        }
        if (b.min < min) {
            min = b.min;
            tMin = b.tMin;
        }
    }
    EXPECT_EQ(max, 1000.0);
    EXPECT_DOUBLE_EQ(tMax, 123'457 * 0.005);
    EXPECT_EQ(min, -1000.0);
    EXPECT_DOUBLE_EQ(tMin, 98'765 * 0.005);

    expectMatchesBruteForce(s, 300.0, 301.0, 7); // a zoomed part, in the wrapped region
    expectMatchesBruteForce(s, 400.0, 700.0, 1);
    expectMatchesBruteForce(s, 617.285, 617.285, 5); // a range of one instant: nothing

    QList<double> t, v;
    SampleStore::toPolyline(buckets, t, v);
    EXPECT_LE(t.size(), 1602);
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
    EXPECT_TRUE(v.contains(1000.0));
    EXPECT_TRUE(v.contains(-1000.0));
}

// decimateOnGrid() takes whole blocks of kBlockRows rows from their summaries. Shapes that could
// trip that: a capacity that is not a multiple of the block (a block wraps around the ring's end),
// a ring that wrapped many times, ties (the first occurrence must win, as row by row), runs of NaN
// longer than a block, many rows at the same time, a clear() in the middle, makeResident() before
// or after rows arrived. Each is compared with reading every row.
TEST(SampleStore, DecimationFromBlockSummariesMatchesReadingEveryRow)
{
    std::mt19937 rng(21);
    std::uniform_int_distribution<int> level(-3, 3); // few levels: many ties
    std::uniform_int_distribution<int> percent(0, 99);
    for (const qsizetype capacity :
         {qsizetype(31), qsizetype(32), qsizetype(1000), qsizetype(1003), qsizetype(5000)}) {
        for (const int rows : {20, 900, 3 * 1003 + 17, 12'345}) {
            SCOPED_TRACE(testing::Message() << "capacity " << capacity << ", rows " << rows);
            SampleStore s(channels(2), capacity);
            if (rows == 900)
                s.makeResident(); // summaries touched before any row
            double t = 0;
            int nanRun = 0;
            for (int i = 0; i < rows; ++i) {
                if (rows == 12'345 && i == 5000)
                    s.clear(); // the row numbers start again at 0
                if (rows == 3 * 1003 + 17 && i == 2000)
                    s.makeResident(); // after the ring wrapped
                t += percent(rng) < 20 ? 0.0 : 0.001 * (1 + percent(rng) % 3); // equal times too
                if (nanRun == 0 && percent(rng) < 2)
                    nanRun = 40; // longer than a block
                const double v = nanRun > 0 ? (--nanRun, kNaN) : double(level(rng));
                appendRow(s, t, {v, -v});
            }
            const double first = s.firstTime();
            const double last = s.lastTime();
            for (const int buckets : {1, 3, 7, 50, 800}) {
                expectMatchesBruteForce(s, first, last, buckets, 1);
                expectMatchesBruteForce(s, first, last, buckets);
                expectMatchesBruteForce(s, first + (last - first) / 3, last, buckets);
                expectMatchesBruteForce(s, first, first + (last - first) / 7, buckets);
            }
            expectMatchesBruteForce(s, last + 1, last + 2, 10); // nothing in range
        }
    }
}

TEST(SampleStore, SparseRangesDecimateToEverySample)
{
    SampleStore s(channels(1), 100);
    for (int i = 0; i < 20; ++i)
        appendRow(s, i, {double(i % 3)});
    QList<double> t, v;
    SampleStore::toPolyline(DecimationCache().slices(s, 0, 0, 19, 1000), t, v);
    EXPECT_EQ(t.size(), 20);
    EXPECT_EQ(v[5], 2.0);
}

TEST(SampleStore, MarkersAreSortedAndBounded)
{
    SampleStore s(channels(1), 10, 3);
    s.addMarker(2.0, QStringLiteral("b"));
    s.addMarker(1.0, QStringLiteral("a"));
    s.addMarker(3.0, QStringLiteral("c"));
    s.addMarker(4.0, QString(1000, QLatin1Char('x')));
    ASSERT_EQ(s.markers().size(), 3u);
    EXPECT_EQ(s.markers().front().text, "b"); // the oldest went
    EXPECT_EQ(s.markers().back().text.size(), SampleStore::kMaxMarkerText);
    EXPECT_EQ(s.markersIn(2.5, 3.0), (QList<SampleMarker>{{3.0, QStringLiteral("c")}}));
}

namespace {

// The CSV's separator and decimal sign follow the default QLocale (the app's language).
class DefaultLocale
{
public:
    explicit DefaultLocale(QLocale::Language language) { QLocale::setDefault(QLocale(language)); }
    ~DefaultLocale() { QLocale::setDefault(m_saved); }
    DefaultLocale(const DefaultLocale &) = delete;
    DefaultLocale &operator=(const DefaultLocale &) = delete;

private:
    QLocale m_saved;
};

QByteArray csvOf(const SampleStore &s, QLocale::Language language = QLocale::English)
{
    const DefaultLocale locale(language);
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    EXPECT_TRUE(s.writeCsv(buffer));
    return buffer.data();
}

std::optional<SampleStore> read(const QByteArray &csv, QString *error = nullptr,
                                const SampleCsvLimits &limits = {})
{
    QBuffer buffer;
    buffer.setData(csv);
    buffer.open(QIODevice::ReadOnly);
    return SampleStore::readCsv(buffer, error, limits);
}

} // namespace

TEST(SampleStore, CsvRoundTripWithMarkers)
{
    QList<SampleChannel> ch = channels(3);
    ch[1].name = QStringLiteral("pressure, \"A\" side");
    ch[2].unit = QStringLiteral("°C");
    SampleStore s(ch, 50);
    s.addMarker(-0.5, QStringLiteral("before the first sample"));
    for (int i = 0; i < 70; ++i) // wrapped
        appendRow(s, i * 0.005 + 0.1,
                  {std::sin(i * 0.1) * 123.456, i % 7 == 0 ? kNaN : 1.0 / (i + 1), -1e-7 * i});
    s.addMarker(s.timeAt(10), QStringLiteral("C1.07 P gain 1.20 → 1.50, \"boost\""));
    s.addMarker(99.0, QStringLiteral("after the last sample"));

    const QByteArray csv = csvOf(s);
    EXPECT_TRUE(csv.startsWith("# ValveTune samples,1\n"
                               "# Separator: comma (,). Decimal sign: point (.). Encoding: UTF-8.\n"
                               "# channel,d1.7,value 0,%\n"));
    EXPECT_TRUE(csv.contains("\ntime_s,d1.7,d1.8,d1.9,marker\n"));
    QString error;
    const std::optional<SampleStore> back = read(csv, &error);
    ASSERT_TRUE(back.has_value()) << error.toStdString();
    EXPECT_EQ(back->channels(), s.channels());
    ASSERT_EQ(back->size(), s.size());
    for (qsizetype i = 0; i < s.size(); ++i) {
        EXPECT_NEAR(back->timeAt(i), s.timeAt(i), 0.5e-6); // times to the microsecond
        for (int c = 0; c < 3; ++c) {
            const double a = s.valueAt(c, i);
            const double b = back->valueAt(c, i);
            EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i << ' ' << c;
        }
    }
    ASSERT_EQ(back->markers().size(), s.markers().size());
    for (std::size_t m = 0; m < s.markers().size(); ++m) {
        EXPECT_NEAR(back->markers()[m].t, s.markers()[m].t, 0.5e-6);
        EXPECT_EQ(back->markers()[m].text, s.markers()[m].text);
    }

    // A range export holds only the rows and markers of the range.
    QBuffer part;
    part.open(QIODevice::WriteOnly);
    {
        const DefaultLocale english(QLocale::English);
        ASSERT_TRUE(s.writeCsv(part, s.timeAt(5), s.timeAt(14)));
    }
    const std::optional<SampleStore> range = read(part.data());
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->size(), 10);
    EXPECT_EQ(range->markers().size(), 1u);
    EXPECT_NEAR(range->firstTime(), s.timeAt(5), 0.5e-6);
}

// A steady clock's time is written to the microsecond, not with every digit of the double.
TEST(SampleStore, CsvTimesHaveMicrosecondPrecision)
{
    SampleStore s(channels(1), 10);
    appendRow(s, 196.63327260100002, {1.0});
    const QByteArray csv = csvOf(s);
    EXPECT_TRUE(csv.contains("\n196.633273,1,\n")) << csv.toStdString();
    EXPECT_TRUE(csvOf(s, QLocale::German).contains("\n196,633273;1;\n"))
        << csvOf(s, QLocale::German).toStdString();
}

TEST(SampleStore, CsvReaderIsBoundedAndRejectsGarbage)
{
    SampleStore s(channels(2), 100);
    for (int i = 0; i < 20; ++i)
        appendRow(s, i, {1, 2});
    const QByteArray csv = csvOf(s);
    QString error;

    SampleCsvLimits fewRows;
    fewRows.maxRows = 10;
    EXPECT_FALSE(read(csv, &error, fewRows).has_value());
    EXPECT_EQ(error, "line 16: more than 10 samples");

    SampleCsvLimits fewChannels;
    fewChannels.maxChannels = 1;
    EXPECT_FALSE(read(csv, &error, fewChannels).has_value());

    QByteArray longLine = csv;
    longLine.append("20," + QByteArray(100'000, '1') + ",2,\n");
    EXPECT_FALSE(read(longLine, &error).has_value());
    EXPECT_TRUE(error.contains("longer than")) << error.toStdString();

    EXPECT_FALSE(read("time_s,a,marker\n1,2,\n", &error).has_value());
    EXPECT_EQ(error, "line 1: not a ValveTune sample file");
    QByteArray badNumber = csv;
    badNumber.append("21,abc,2,\n");
    EXPECT_FALSE(read(badNumber, &error).has_value());
    QByteArray backwards = csv;
    backwards.append("3,1,2,\n");
    EXPECT_FALSE(read(backwards, &error).has_value());
    EXPECT_TRUE(error.endsWith("time goes backwards"));
    QByteArray wrongColumns = csv;
    wrongColumns.append("30,1,\n");
    EXPECT_FALSE(read(wrongColumns, &error).has_value());

    const std::optional<SampleStore> empty = read(csvOf(SampleStore(channels(2), 5)));
    ASSERT_TRUE(empty.has_value());
    EXPECT_TRUE(empty->isEmpty());
}

// German and English issue: a German export uses ';' and decimal ',' and says so; it reads back
// exactly, and so does a file of the first version (',' and '.', no statement line).
TEST(SampleStore, GermanCsvUsesSemicolonAndDecimalCommaAndRoundTrips)
{
    QList<SampleChannel> ch = channels(2);
    ch[0].name = QStringLiteral("Druck; A-Seite, \"roh\"");
    SampleStore s(ch, 20);
    for (int i = 0; i < 12; ++i)
        appendRow(s, 0.125 * i + 1e-9, {i % 5 == 0 ? kNaN : -1.5 * i, 1e-7 * i});
    s.addMarker(s.timeAt(3), QStringLiteral("C1.13 1,20 → 1,50; Test"));

    const QByteArray csv = csvOf(s, QLocale::German);
    EXPECT_TRUE(csv.startsWith(
        "# ValveTune samples;1\n"
        "# Trennzeichen: Semikolon (;). Dezimalzeichen: Komma (,). Kodierung: UTF-8.\n"
        "# channel;d1.7;\"Druck; A-Seite, \"\"roh\"\"\";%\n"
        "# channel;d1.8;value 1;%\n"
        "time_s;d1.7;d1.8;marker\n"))
        << csv.toStdString();
    EXPECT_TRUE(csv.contains("\n0,125000;-1,5;1e-07;\n")) << csv.toStdString(); // µs
    EXPECT_FALSE(csv.contains("0.125")) << "no decimal point in a German file";
    EXPECT_TRUE(csv.contains(";\"C1.13 1,20 → 1,50; Test\"\n")) << csv.toStdString();

    QString error;
    const std::optional<SampleStore> back = read(csv, &error);
    ASSERT_TRUE(back.has_value()) << error.toStdString();
    EXPECT_EQ(back->channels(), s.channels());
    ASSERT_EQ(back->size(), s.size());
    for (qsizetype i = 0; i < s.size(); ++i) {
        EXPECT_NEAR(back->timeAt(i), s.timeAt(i), 0.5e-6);
        for (int c = 0; c < 2; ++c) {
            const double a = s.valueAt(c, i);
            const double b = back->valueAt(c, i);
            EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i << ' ' << c;
        }
    }
    ASSERT_EQ(back->markers().size(), 1u);
    EXPECT_NEAR(back->markers().front().t, s.markers().front().t, 0.5e-6);
    EXPECT_EQ(back->markers().front().text, s.markers().front().text);

    // A decimal point in a German file is refused, not read as a different number.
    QByteArray pointed = csv;
    pointed.append("5,5;1.5;2;\n");
    EXPECT_FALSE(read(pointed, &error).has_value());
    EXPECT_TRUE(error.endsWith("'1.5' is not a number")) << error.toStdString();
}

TEST(SampleStore, CsvOfTheFirstVersionStillReads)
{
    const QByteArray v1 = "# ValveTune samples,1\n# channel,d1.7,value 0,%\ntime_s,d1.7,marker\n"
                          "0.5,1.25,\n0.75,,\"a, b\"\n1,-2.5e-3,\n";
    QString error;
    const std::optional<SampleStore> back = read(v1, &error);
    ASSERT_TRUE(back.has_value()) << error.toStdString();
    ASSERT_EQ(back->size(), 2);
    EXPECT_EQ(back->timeAt(1), 1.0);
    EXPECT_FLOAT_EQ(static_cast<float>(back->valueAt(0, 1)), -2.5e-3f);
    ASSERT_EQ(back->markers().size(), 1u);
    EXPECT_EQ(back->markers().front().text, "a, b");
    EXPECT_FALSE(read("# ValveTune samples|1\ntime_s,marker\n", &error).has_value());
    EXPECT_EQ(error, "line 1: not a ValveTune sample file");
}

// Issue #21 (endurance): the ring's hour becomes resident when monitoring starts, not 28 B a
// poll over the hour; filling it afterwards adds nothing.
TEST(SampleStore, MakeResidentTouchesTheRingOnceAndFillingItAddsNoMemory)
{
    if (!vt::test::kResidentMemoryIsMeaningful)
        GTEST_SKIP() << "AddressSanitizer's quarantine keeps every freed temporary resident";
    constexpr qsizetype kRows = 400'000; // 400 000 × (8 + 5 × 4) B = 11.2 MB
    // Fresh pages for the ring, as in a new process: not heap memory earlier tests made resident
    // and freed (glibc reuses free heap chunks, and raises its mmap threshold after large frees).
    mallopt(M_MMAP_THRESHOLD, 1024 * 1024);
    malloc_trim(0);
    SampleStore store(channels(5), kRows);
    const qint64 ring = SampleStore::ringBytes(5, kRows);
    const qint64 before = vt::test::residentBytes();
    ASSERT_GT(before, 0);
    EXPECT_FALSE(store.isResident());
    store.makeResident();
    EXPECT_TRUE(store.isResident());
    const qint64 resident = vt::test::residentBytes();
    EXPECT_GE(resident - before, ring * 9 / 10);

    for (qsizetype i = 0; i < kRows; ++i)
        appendRow(store, static_cast<double>(i) * 0.005, {1, 2, 3, 4, 5});
    EXPECT_EQ(store.size(), kRows);
    EXPECT_LT(vt::test::residentBytes() - resident, ring / 20);
}

TEST(SampleStore, MakeResidentKeepsTheSamplesOfAWrappedRing)
{
    SampleStore store(channels(2), 10);
    for (int i = 0; i < 15; ++i)
        appendRow(store, i, {double(i), -double(i)});
    store.makeResident();
    store.makeResident(); // idempotent
    ASSERT_EQ(store.size(), 10);
    for (qsizetype i = 0; i < 10; ++i) {
        EXPECT_EQ(store.timeAt(i), double(5 + i));
        EXPECT_EQ(store.valueAt(1, i), -double(5 + i));
    }
    SampleStore partly(channels(2), 10);
    for (int i = 0; i < 4; ++i)
        appendRow(partly, i, {double(i), double(i)});
    partly.makeResident();
    ASSERT_EQ(partly.size(), 4);
    EXPECT_EQ(partly.valueAt(0, 3), 3.0);
    appendRow(partly, 4, {4, 4});
    EXPECT_EQ(partly.timeAt(4), 4.0);
    EXPECT_EQ(DecimationCache().slices(partly, 0, 0, 4, 100).size(), 5u);
}
