// MonitorPlot without a device: journal labels that would sit on each other take lanes or give
// way (their whole text on hover), and an exported plot carries a title with the modules, the
// date and the time.
#include "widgets/monitor/monitor_plot.h"

#include <QDate>
#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

std::vector<QCPItemText *> labels(const ui::MonitorPlot &plot)
{
    std::vector<QCPItemText *> out;
    for (int i = 0; i < plot.itemCount(); ++i)
        if (auto *text = qobject_cast<QCPItemText *>(plot.item(i)))
            out.push_back(text);
    return out;
}

TEST(MonitorPlot, CrowdedJournalLabelsDoNotOverlapAndShowTheirTextOnHover)
{
    ui::MonitorPlot plot;
    plot.resize(800, 400);
    plot.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot));
    plot.xAxis->setRange(0, 10);
    plot.replot();
    std::vector<model::SampleMarker> markers;
    const QString longText = QStringLiteral(
        "module 1 C1.07 P gain 1.200 V/V → 1.500 V/V, written and read back, verified");
    for (int i = 0; i < 10; ++i)
        markers.push_back(
            {5.0 + 0.01 * i, i == 0 ? longText : QStringLiteral("E17 = 2 (%1)").arg(i)});
    plot.setMarkers(markers);
    const auto shown = labels(plot);
    ASSERT_FALSE(shown.empty());
    EXPECT_LE(shown.size(), 4u); // one per lane; the others give way
    QSet<double> rows;
    for (QCPItemText *text : shown)
        rows.insert(text->position->coords().y());
    EXPECT_EQ(static_cast<std::size_t>(rows.size()), shown.size()); // no two on one row
    EXPECT_LT(shown.front()->text().size(), longText.size());       // shortened …
    const QString hover = plot.markerTextNear(plot.xAxis->coordToPixel(5.0));
    EXPECT_TRUE(hover.contains(longText)) << hover.toStdString(); // … whole on hover
    EXPECT_TRUE(plot.markerTextNear(plot.xAxis->coordToPixel(1.0)).isEmpty());
}

TEST(MonitorPlot, ExportCarriesTitleModulesDateAndTime)
{
    ui::MonitorPlot plot;
    plot.resize(800, 400);
    model::ModuleInfo module;
    module.address = 2;
    module.identification.family = "dma-pn-v51";
    module.identification.version = "51.00";
    plot.setModules({module});
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("plot.png"));
    ASSERT_TRUE(plot.exportPng(png));
    const QString title = plot.lastExportTitle();
    EXPECT_TRUE(title.contains(QStringLiteral("module 2 (dma-pn-v51 51.00)")))
        << title.toStdString();
    EXPECT_TRUE(title.contains(QDate::currentDate().toString(Qt::ISODate))) << title.toStdString();
    EXPECT_EQ(plot.plotLayout()->rowCount(), 1); // the title goes again after the export
    const QImage image(png);
    EXPECT_GT(image.height(), 400); // the title row above the plot
    ASSERT_TRUE(plot.exportPdf(dir.filePath(QStringLiteral("plot.pdf"))));
}

} // namespace
} // namespace vt::test
