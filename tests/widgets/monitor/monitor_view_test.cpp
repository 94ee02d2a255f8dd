// MonitorView offscreen against the simulator: write markers with old → new text,
// CSV export round trip, PNG/PDF export, no redraw while hidden, redraws coalesced (≤ 25/s),
// decimation to about one min/max pair per pixel, the cursor read-out, channel choice.
#include "model/session/write_job.h"
#include "sim_rig.h"
#include "widgets/monitor/monitor_plot.h"
#include "widgets/monitor/monitor_view.h"

#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QLocale>
#include <QSet>
#include <QTemporaryDir>
#include <cmath>

namespace vt::test {
namespace {

using ui::MonitorView;

// Runs the monitor until the first module's store holds `rows` samples.
bool record(MonitorView &view, const SimRig &rig, qsizetype rows, double hz = 200)
{
    view.setRate(hz);
    view.start();
    const model::SampleStore *store = view.session().store(rig.module().address);
    return waitUntil([&] { return store && store->size() >= rows; }, kWaitMs);
}

// Shows the view at `size` and hands it the rig's connection, as the main window does.
void showOn(MonitorView &view, const SimRig &rig, QSize size = {800, 500})
{
    view.resize(size);
    view.show();
    view.setConnection(rig.connection.get(), rig.modules);
}

std::vector<QString> markerTexts(const ui::MonitorPlot &plot)
{
    std::vector<QString> texts;
    for (int i = 0; i < plot.itemCount(); ++i) {
        if (auto *text = qobject_cast<QCPItemText *>(plot.item(i)))
            texts.push_back(text->text());
    }
    return texts;
}

TEST(MonitorView, ParameterWriteAppearsAsAMarkerWithOldAndNewValue)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    showOn(view, *rig, {900, 600});
    ASSERT_TRUE(record(view, *rig, 20));

    // A write as the parameter editor does it: WriteJob, then journalWrites() with its items.
    const dev::ParamMeta &gain = rig->row("C1.07");
    const auto before = rig->read("C1.07");
    ASSERT_TRUE(before);
    const double target = *before == gain.max ? gain.max - 1 : *before + 1;
    model::WriteItem item;
    item.row = &gain;
    item.before = *before;
    item.value = target;
    model::WriteJob job(rig->connection->access(), rig->module().address, *rig->module().dictionary,
                        {item}, model::AuditOrigin::Editor);
    QSignalSpy finished(&job, &model::WriteJob::finished);
    job.start();
    ASSERT_TRUE(finished.wait(kWaitMs));
    ASSERT_EQ(job.items().front().status, model::WriteStatus::Verified);
    view.journalWrites(rig->module().address, job.items());

    const QString expected =
        QStringLiteral("C1.07 %1 → %2")
            .arg(QString::fromStdString(dev::formatValue(gain, *before, dev::Language::English)),
                 QString::fromStdString(dev::formatValue(gain, target, dev::Language::English)));
    ASSERT_EQ(view.session().journal().markers().size(), 1u);
    EXPECT_EQ(view.session().journal().markers().front().text, expected);
    // On the time axis once the next redraw comes.
    EXPECT_TRUE(waitUntil(
        [&] {
            const auto texts = markerTexts(*view.plot());
            return std::find(texts.begin(), texts.end(), expected) != texts.end();
        },
        kWaitMs));
    // Unchanged values were not sent: no marker.
    model::WriteItem same = job.items().front();
    same.status = model::WriteStatus::Unchanged;
    view.journalWrites(rig->module().address, {same});
    EXPECT_EQ(view.session().journal().markers().size(), 1u);
    view.pause();
}

TEST(MonitorView, CsvExportRoundTripsWithTheMarkers)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    view.setConnection(rig->connection.get(), rig->modules);
    ASSERT_TRUE(record(view, *rig, 100));
    model::WriteItem item;
    item.row = &rig->row("C1.07");
    item.before = 100.0;
    item.value = 120.0;
    item.status = model::WriteStatus::Verified;
    view.journalWrites(rig->module().address, {item});
    ASSERT_TRUE(record(view, *rig, 150));
    view.pause();

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath("all.csv");
    QString error;
    ASSERT_TRUE(view.exportCsv(path, false, &error)) << error.toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const auto back = model::SampleStore::readCsv(file, &error);
    ASSERT_TRUE(back) << error.toStdString();
    const model::SampleStore &store = *view.session().store(rig->module().address);
    ASSERT_EQ(back->size(), store.size());
    ASSERT_EQ(back->channels(), store.channels());
    for (qsizetype i = 0; i < store.size(); ++i) {
        // CSV times are rounded to the µs: at most half a µs off, plus the binary error of a
        // time that lies exactly on the half (0.1045745 s is stored as 0.10457450000000001).
        ASSERT_NEAR(back->timeAt(i), store.timeAt(i), 0.5e-6 + 1e-12) << i;
        for (int c = 0; c < store.channelCount(); ++c) {
            const double a = store.valueAt(c, i), b = back->valueAt(c, i);
            ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i << " " << c;
        }
    }
    ASSERT_EQ(back->markers().size(), 1u);
    EXPECT_EQ(back->markers().front().text, view.session().journal().markers().front().text);
    EXPECT_NEAR(back->markers().front().t, view.session().journal().markers().front().t, 0.5e-6);

    // The visible range only: the rows inside the time axis' range.
    view.setFollowing(false);
    const double t0 = store.timeAt(10), t1 = store.timeAt(49);
    view.plot()->xAxis->setRange(t0, t1);
    const QString part = dir.filePath("visible.csv");
    ASSERT_TRUE(view.exportCsv(part, true, &error)) << error.toStdString();
    QFile partFile(part);
    ASSERT_TRUE(partFile.open(QIODevice::ReadOnly));
    const auto visible = model::SampleStore::readCsv(partFile, &error);
    ASSERT_TRUE(visible) << error.toStdString();
    EXPECT_EQ(visible->size(), store.upperBound(t1) - store.lowerBound(t0));
    EXPECT_NEAR(visible->firstTime(), t0, 0.5e-6);
}

TEST(MonitorView, ExportsThePlotAsPngAndPdf)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    showOn(view, *rig);
    ASSERT_TRUE(record(view, *rig, 50));
    view.pause();
    QTemporaryDir dir;
    const QString png = dir.filePath("plot.png");
    ASSERT_TRUE(view.exportPng(png));
    const QImage image(png);
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(image.width(), 100);
    EXPECT_GT(image.height(), 100);
    // Not a blank canvas: background, axes and the graphs' colours.
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2)
            colours.insert(image.pixel(x, y));
    }
    EXPECT_GE(colours.size(), 4);
    const QString pdf = dir.filePath("plot.pdf");
    ASSERT_TRUE(view.exportPdf(pdf));
    QFile file(pdf);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.read(5).startsWith("%PDF-"));
}

TEST(MonitorView, DoesNotRedrawWhileHidden)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    view.setConnection(rig->connection.get(), rig->modules);
    ASSERT_TRUE(record(view, *rig, 100)); // 0.5 s of samples at 200 Hz, never shown
    EXPECT_EQ(view.replotCount(), 0);
    view.resize(800, 500);
    view.show();
    EXPECT_TRUE(waitUntil([&] { return view.replotCount() > 0; }, kWaitMs));
    view.hide();
    const int shown = view.replotCount();
    const qsizetype rows = view.session().store(rig->module().address)->size();
    ASSERT_TRUE(record(view, *rig, rows + 100));
    EXPECT_EQ(view.replotCount(), shown);
    view.pause();
}

TEST(MonitorView, RedrawsAreCoalescedAtTheLinksFullRate)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    showOn(view, *rig);
    view.setRate(0); // as fast as the link allows: thousands of samples per second here
    view.start();
    const int address = rig->module().address;
    ASSERT_TRUE(waitUntil([&] { return view.replotCount() > 0; })); // the GUI redraws at all

    // The window ends when a burst of samples has arrived and the GUI has redrawn in it; a loaded
    // machine only makes it longer. Redraws are at least kMinRedrawMs apart, less up to 5 % by
    // which a coarse QTimer may fire early, so the window holds at most one more than its length
    // allows. Within the wait bound that is far fewer than the samples: one redraw per sample,
    // or per few, breaks it on any machine (and ends the window at once).
    constexpr int kSpacingMs = MonitorView::kMinRedrawMs * 95 / 100;
    constexpr quint64 kSamples = 10'000;
    static_assert(static_cast<quint64>(1 + kWaitMs / kSpacingMs) < kSamples);
    const quint64 samplesBefore = view.session().samples(address);
    const int before = view.replotCount();
    QElapsedTimer clock;
    clock.start();
    qint64 ms = 0;
    int replots = 0;
    ASSERT_TRUE(waitUntil([&] {
        ms = clock.elapsed();
        replots = view.replotCount() - before;
        const bool burst = view.session().samples(address) - samplesBefore >= kSamples;
        return (burst && replots > 0) || replots > 1 + ms / kSpacingMs;
    }));
    view.pause();
    EXPECT_LE(replots, 1 + ms / kSpacingMs) << replots << " redraws in " << ms << " ms";
}

TEST(MonitorView, DecimatesToAboutOnePairPerPixel)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    view.resize(600, 400);
    view.show();
    view.setConnection(rig->connection.get(), rig->modules);
    view.setRate(0);
    view.start();
    const model::SampleStore *store = view.session().store(rig->module().address);
    ASSERT_TRUE(waitUntil([&] { return store->size() >= 20000; }, kWaitMs));
    view.pause();
    ui::MonitorPlot &plot = *view.plot();
    plot.loadRange(store->firstTime(), store->lastTime());
    const int pixels = std::max(100, plot.axisRect()->width());
    const auto channels = static_cast<qsizetype>(plot.channels().size());
    EXPECT_LE(plot.pointCount(), channels * (2 * pixels + 4));
    EXPECT_LT(plot.pointCount(), channels * store->size() / 4);
    plot.setDecimation(false);
    plot.loadRange(store->firstTime(), store->lastTime());
    EXPECT_EQ(plot.pointCount(), channels * store->size());
}

TEST(MonitorView, CursorReadsOutEveryChannelAtOneTime)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    view.setConnection(rig->connection.get(), rig->modules);
    ASSERT_TRUE(record(view, *rig, 30));
    view.pause();
    const model::SampleStore &store = *view.session().store(rig->module().address);
    const QStringList lines = view.plot()->readout(store.timeAt(5));
    ASSERT_EQ(lines.size(), 1 + store.channelCount());
    EXPECT_TRUE(lines.front().startsWith("t = ")) << lines.front().toStdString();
    EXPECT_TRUE(lines.at(1).startsWith("d1.10 ")) << lines.at(1).toStdString();
    EXPECT_TRUE(lines.at(1).endsWith(" V")) << lines.at(1).toStdString();
    EXPECT_TRUE(lines.at(3).startsWith("d1.07 ")) << lines.at(3).toStdString();
    // Numbers in the UI language's notation.
    const QLocale previous;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    const QStringList german = view.plot()->readout(store.timeAt(5));
    QLocale::setDefault(previous);
    const QString number = german.at(1).section(QLatin1Char(' '), 1, 1); // "d1.10 0,000 V"
    EXPECT_TRUE(number.contains(QLatin1Char(','))) << german.at(1).toStdString();
    EXPECT_FALSE(number.contains(QLatin1Char('.'))) << german.at(1).toStdString();
}

// Switching the language at run time: the plot's tick labels follow the new language's number
// notation too (they kept German commas in an English UI before).
TEST(MonitorView, ALanguageChangeSwitchesThePlotsNumberNotation)
{
    MonitorView view;
    const QLocale previous;
    for (const QLocale::Language language : {QLocale::German, QLocale::English}) {
        QLocale::setDefault(QLocale(language));
        QEvent change(QEvent::LanguageChange);
        QCoreApplication::sendEvent(&view, &change);
        EXPECT_EQ(view.plot()->locale().language(), language);
        EXPECT_EQ(view.plot()->locale().decimalPoint(),
                  language == QLocale::German ? QStringLiteral(",") : QStringLiteral("."));
    }
    QLocale::setDefault(previous);
}

TEST(MonitorView, AnyDisplayValueOfAnyModuleAndOneAxisPerUnit)
{
    auto rig = connectSim("dma-pn-v51", 2);
    ASSERT_TRUE(rig);
    MonitorView view;
    showOn(view, *rig);
    // Default: five channels of the first module, volts and amperes.
    EXPECT_EQ(view.plot()->channels().size(), 5u);
    EXPECT_EQ(view.plot()->unitAxisCount(), 2);
    const auto offered = model::monitorableRows(rig->module(1));
    ASSERT_FALSE(offered.empty());
    std::map<int, std::vector<const dev::ParamMeta *>> selection;
    selection[rig->module(0).address] = view.session().channels(rig->module(0).address);
    selection[rig->module(1).address] = {&rig->row("d1.11", 1)};
    view.setChannels(selection);
    EXPECT_EQ(view.plot()->channels().size(), 6u);
    EXPECT_EQ(view.plot()->channels().back().id,
              QStringLiteral("%1/d1.11").arg(rig->module(1).address));
    view.setRate(100);
    view.start();
    const model::SampleStore *second = view.session().store(rig->module(1).address);
    ASSERT_TRUE(second);
    EXPECT_TRUE(waitUntil([&] { return second->size() >= 20; }, kWaitMs));
    EXPECT_TRUE(
        view.achievedRateText().contains(QStringLiteral("%1: ").arg(rig->module(1).address)))
        << view.achievedRateText().toStdString();
    view.pause();
}

TEST(MonitorView, DraggingTheTimeAxisStopsFollowing)
{
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    MonitorView view;
    showOn(view, *rig);
    ASSERT_TRUE(record(view, *rig, 40));
    EXPECT_TRUE(view.isFollowing());
    view.plot()->xAxis->moveRange(-0.1); // what a mouse drag does
    EXPECT_FALSE(view.isFollowing());
    view.pause();
}

TEST(MonitorView, ALostLinkIsReportedOnceNotForEveryPoll)
{
    // The link is cut after 60 frames: identify, then some polls, then every poll fails at once.
    auto rig = connectSim({"dma-pn-v51", 1, {}, link::parseFaultSpec(u"cut=60").value(), {}});
    ASSERT_TRUE(rig);
    MonitorView view;
    QSignalSpy status(&view, &MonitorView::statusMessage);
    view.setConnection(rig->connection.get(), rig->modules);
    view.setRate(200);
    view.start();
    const int module = rig->module().address;
    ASSERT_TRUE(waitUntil([&] { return view.session().scheduler()->failed(module) >= 20; }));
    // "… was lost", then "… is not open" for every further poll: each said once.
    EXPECT_GE(status.count(), 1);
    EXPECT_LE(status.count(), 2);
    EXPECT_TRUE(status.front().front().toString().startsWith(
        QStringLiteral("Monitor, module %1: ").arg(module)))
        << status.front().front().toString().toStdString();
    view.clearConnection();
    EXPECT_FALSE(view.isRunning());
}

} // namespace
} // namespace vt::test
