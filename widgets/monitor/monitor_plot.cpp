#include "monitor_plot.h"

#include <QDateTime>
#include <QFontMetrics>
#include <QLocale>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vt::ui {

namespace {

// Distinct on white and in grey print; the first five are the default channels.
const QColor kPalette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                           QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                           QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f),
                           QColor(0xbc, 0xbd, 0x22), QColor(0x17, 0xbe, 0xcf)};
constexpr int kMinBuckets = 100;
constexpr std::size_t kMaxMarkersDrawn = 200; // more would be an unreadable comb
constexpr std::size_t kMarkerLanes = 4;       // label rows below the top of the plot
constexpr int kMarkerLabelPx = 220;           // a longer journal text is shortened ("…")
constexpr double kMarkerHoverPx = 4;          // the mouse this near a marker line shows its text
const QColor kMarkerColor(0x60, 0x60, 0x60);

} // namespace

MonitorPlot::MonitorPlot(QWidget *parent) : QCustomPlot(parent)
{
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setNoAntialiasingOnDrag(true);
    legend->setVisible(true);
    QFont small = legend->font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.85));
    legend->setFont(small);
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    m_cursorLine = new QCPItemLine(this);
    m_cursorLine->setLayer(QStringLiteral("overlay"));
    m_cursorLine->start->setTypeX(QCPItemPosition::ptPlotCoords);
    m_cursorLine->start->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_cursorLine->end->setTypeX(QCPItemPosition::ptPlotCoords);
    m_cursorLine->end->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_cursorLine->start->setCoords(0, 0);
    m_cursorLine->end->setCoords(0, 1);
    m_cursorLine->setPen(QPen(Qt::black, 0, Qt::DashLine));
    m_cursorLine->setVisible(false);
    setMouseTracking(true);
    retranslate();
}

MonitorPlot::~MonitorPlot() = default;

void MonitorPlot::retranslate()
{
    setLocale(QLocale()); // tick labels in the UI language's notation ("2,5" / "2.5")
    xAxis->setLabel(tr("time (s)"));
}

QCPAxis *MonitorPlot::unitAxis(const QString &unit) const
{
    for (const auto &[name, axis] : m_unitAxes) {
        if (name == unit)
            return axis;
    }
    return nullptr;
}

QCPAxis *MonitorPlot::axisFor(const QString &unit)
{
    if (QCPAxis *axis = unitAxis(unit))
        return axis;
    QCPAxis *axis = nullptr;
    const std::size_t n = m_unitAxes.size();
    if (n == 0)
        axis = yAxis;
    else if (n == 1)
        axis = yAxis2;
    else
        axis = axisRect()->addAxis(n % 2 == 0 ? QCPAxis::atLeft : QCPAxis::atRight);
    axis->setVisible(true);
    axis->setTickLabels(true);
    axis->setLabel(unit.isEmpty() ? QStringLiteral("–") : unit);
    m_unitAxes.emplace_back(unit, axis);
    return axis;
}

void MonitorPlot::setChannels(std::vector<PlotChannel> channels)
{
    clearGraphs();
    for (const auto &[unit, axis] : m_unitAxes) {
        if (axis != yAxis && axis != yAxis2)
            axisRect()->removeAxis(axis);
    }
    m_unitAxes.clear();
    yAxis2->setVisible(false);
    m_channels = std::move(channels);
    m_caches.assign(m_channels.size(), model::DecimationCache());
    std::size_t i = 0;
    for (const PlotChannel &channel : m_channels) {
        QCPGraph *graph = addGraph(xAxis, axisFor(channel.unit));
        // Width 1: a wider antialiased pen makes Qt stroke each polyline as a filled outline,
        // 250 times slower here (docs/PERFORMANCE.md, "Monitor plot redraw").
        graph->setPen(QPen(kPalette[i++ % std::size(kPalette)], 1));
        graph->setName(
            channel.unit.isEmpty()
                ? QStringLiteral("%1 %2").arg(channel.id, channel.name)
                : QStringLiteral("%1 %2 (%3)").arg(channel.id, channel.name, channel.unit));
    }
    if (m_unitAxes.empty())
        yAxis->setLabel(QString());
    QList<QCPAxis *> zoomAxes{xAxis};
    for (const auto &[unit, axis] : m_unitAxes)
        zoomAxes.append(axis);
    axisRect()->setRangeDragAxes(zoomAxes);
    axisRect()->setRangeZoomAxes(zoomAxes);
}

void MonitorPlot::loadRange(double t0, double t1)
{
    if (!(t1 > t0))
        t1 = t0 + 1.0;
    xAxis->setRange(t0, t1);
    const int buckets = std::max(kMinBuckets, axisRect()->width());
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        const PlotChannel &channel = m_channels[i];
        const model::SampleStore &store = *channel.store;
        // One sample beyond each edge, so the lines reach the plot's borders.
        const qsizetype first = std::max<qsizetype>(0, store.lowerBound(t0) - 1);
        const qsizetype last = std::min(store.size() - 1, store.upperBound(t1));
        m_times.clear();
        m_values.clear();
        if (last >= first && store.size() > 0) {
            const double from = store.timeAt(first);
            const double to = store.timeAt(last);
            // Decimated: one slice more on each side, so the lines reach the borders there, too.
            const double w = (t1 - t0) / buckets;
            if (m_decimate && last - first + 1 > 2 * static_cast<qsizetype>(buckets))
                model::SampleStore::toPolyline(
                    m_caches[i].slices(store, channel.column, t0 - w, t1 + w, buckets + 2), m_times,
                    m_values);
            else
                store.copyRange(channel.column, from, to, m_times, m_values);
        }
        graph(static_cast<int>(i))->setData(m_times, m_values, true);
    }
}

void MonitorPlot::forgetDecimation()
{
    for (model::DecimationCache &cache : m_caches)
        cache.reset();
}

void MonitorPlot::rescaleValueAxes()
{
    for (const auto &[unit, axis] : m_unitAxes) {
        bool found = false;
        QCPRange range;
        for (QCPGraph *g : axis->graphs()) {
            bool has = false;
            const QCPRange r = g->getValueRange(has, QCP::sdBoth, xAxis->range());
            if (!has)
                continue;
            range = found ? QCPRange(std::min(range.lower, r.lower), std::max(range.upper, r.upper))
                          : r;
            found = true;
        }
        if (!found)
            continue;
        const double span = range.size();
        const double margin = span > 0 ? span * 0.05 : std::max(0.5, std::abs(range.lower) * 0.1);
        axis->setRange(range.lower - margin, range.upper + margin);
    }
}

void MonitorPlot::removeMarkerItems()
{
    for (QCPAbstractItem *item : m_markerItems)
        removeItem(item);
    m_markerItems.clear();
}

void MonitorPlot::setMarkers(const std::vector<model::SampleMarker> &markers)
{
    removeMarkerItems();
    m_shownMarkers.clear();
    const QCPRange range = xAxis->range();
    const QFontMetrics metrics(font());
    // Labels take the first of a few lanes below the top where they do not touch the label
    // before them; one that fits nowhere keeps its line, its text is on hover.
    std::vector<double> laneEnd(kMarkerLanes, -std::numeric_limits<double>::infinity());
    std::size_t drawn = 0;
    for (const model::SampleMarker &marker : markers) {
        if (marker.t < range.lower || marker.t > range.upper)
            continue;
        if (drawn == kMaxMarkersDrawn)
            break;
        ++drawn;
        m_shownMarkers.push_back(marker);
        auto *line = new QCPItemLine(this);
        line->start->setTypeX(QCPItemPosition::ptPlotCoords);
        line->start->setTypeY(QCPItemPosition::ptAxisRectRatio);
        line->end->setTypeX(QCPItemPosition::ptPlotCoords);
        line->end->setTypeY(QCPItemPosition::ptAxisRectRatio);
        line->start->setCoords(marker.t, 0);
        line->end->setCoords(marker.t, 1);
        line->setPen(QPen(kMarkerColor, 1, Qt::DotLine));
        m_markerItems.push_back(line);

        const QString label = metrics.elidedText(marker.text, Qt::ElideRight, kMarkerLabelPx);
        const double x = xAxis->coordToPixel(marker.t);
        const double width = metrics.horizontalAdvance(label) + 6;
        // Texts in the right half open to the left, so they are not cut at the plot's edge.
        const bool rightHalf = marker.t > range.center();
        const double left = rightHalf ? x - width : x;
        const auto lane = std::find_if(laneEnd.begin(), laneEnd.end(),
                                       [&](double end) { return left > end + 4; });
        if (lane == laneEnd.end())
            continue;
        *lane = left + width;
        auto *text = new QCPItemText(this);
        text->position->setTypeX(QCPItemPosition::ptPlotCoords);
        text->position->setTypeY(QCPItemPosition::ptAbsolute);
        text->position->setCoords(marker.t, axisRect()->top() + 2 +
                                                static_cast<double>(lane - laneEnd.begin()) *
                                                    (metrics.height() + 3));
        text->setPositionAlignment((rightHalf ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
        text->setText(label);
        text->setColor(kMarkerColor.darker(150));
        text->setBrush(QBrush(QColor(255, 255, 255, 200)));
        text->setClipToAxisRect(true);
        m_markerItems.push_back(text);
    }
}

QString MonitorPlot::markerTextNear(double pixelX) const
{
    QStringList texts;
    for (const model::SampleMarker &marker : m_shownMarkers)
        if (std::abs(xAxis->coordToPixel(marker.t) - pixelX) <= kMarkerHoverPx)
            texts << marker.text;
    return texts.join(QLatin1Char('\n'));
}

void MonitorPlot::setModules(const std::vector<model::ModuleInfo> &modules)
{
    m_modules = modules;
}

QString MonitorPlot::exportTitle(const QDateTime &when) const
{
    QStringList modules;
    for (const model::ModuleInfo &m : m_modules)
        modules << tr("module %1 (%2 %3)")
                       .arg(m.address)
                       .arg(QString::fromStdString(m.identification.family),
                            QString::fromStdString(m.identification.version));
    const QString time = when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    return modules.isEmpty()
               ? tr("ValveTune monitor, %1").arg(time)
               : tr("ValveTune monitor: %1, %2").arg(modules.join(QStringLiteral(", ")), time);
}

bool MonitorPlot::exportWithTitle(const std::function<bool(int, int)> &save)
{
    // The file says what it shows and when: a title row above the plot while it is written.
    auto *title = new QCPTextElement(this, exportTitle(QDateTime::currentDateTime()));
    title->setObjectName(QStringLiteral("exportTitle"));
    plotLayout()->insertRow(0);
    plotLayout()->addElement(0, 0, title);
    const QSize s = exportSize();
    const QCPLayoutElement *element = title; // the size hint is public on the base
    const bool ok = save(s.width(), s.height() + element->minimumOuterSizeHint().height());
    m_lastExportTitle = title->text();
    plotLayout()->remove(title);
    plotLayout()->simplify();
    replot();
    return ok;
}

qsizetype MonitorPlot::pointCount() const
{
    qsizetype n = 0;
    for (int i = 0; i < graphCount(); ++i)
        n += graph(i)->dataCount();
    return n;
}

void MonitorPlot::refresh(double t0, double t1, const std::vector<model::SampleMarker> &markers,
                          bool rescale)
{
    loadRange(t0, t1);
    setMarkers(markers);
    if (rescale)
        rescaleValueAxes();
    replot();
    ++m_replots;
}

QStringList MonitorPlot::readout(double t) const
{
    const QLocale locale;
    QStringList lines{tr("t = %1 s").arg(locale.toString(t, 'f', 3))};
    for (const PlotChannel &channel : m_channels) {
        const model::SampleStore &store = *channel.store;
        QString value = QStringLiteral("–");
        if (store.size() > 0) {
            qsizetype i = std::min(store.lowerBound(t), store.size() - 1);
            if (i > 0 && std::abs(store.timeAt(i - 1) - t) <= std::abs(store.timeAt(i) - t))
                --i;
            const double v = store.valueAt(channel.column, i);
            if (!std::isnan(v))
                value = locale.toString(v, 'f', channel.decimals);
        }
        lines.append(channel.unit.isEmpty()
                         ? QStringLiteral("%1 %2").arg(channel.id, value)
                         : QStringLiteral("%1 %2 %3").arg(channel.id, value, channel.unit));
    }
    return lines;
}

void MonitorPlot::setCursorAt(std::optional<double> t)
{
    m_cursorTime = t;
    m_cursorLine->setVisible(t.has_value());
    if (t) {
        m_cursorLine->start->setCoords(*t, 0);
        m_cursorLine->end->setCoords(*t, 1);
    }
    // Only the overlay layer: the graphs are not drawn again for a cursor move. A hidden plot
    // has no paint buffer yet; its next refresh() draws the cursor.
    if (isVisible())
        layer(QStringLiteral("overlay"))->replot();
}

void MonitorPlot::mouseMoveEvent(QMouseEvent *event)
{
    QCustomPlot::mouseMoveEvent(event);
    if (axisRect()->rect().contains(event->pos()) && event->buttons() == Qt::NoButton) {
        emit hovered(xAxis->pixelToCoord(event->position().x()));
        // A journal entry's whole text, however its label was shortened or left out.
        const QString text = markerTextNear(event->position().x());
        if (!text.isEmpty())
            QToolTip::showText(event->globalPosition().toPoint(), text, this);
        else
            QToolTip::hideText();
    }
}

QSize MonitorPlot::exportSize() const
{
    return width() >= 200 && height() >= 150 ? size() : QSize(1000, 600);
}

bool MonitorPlot::exportPng(const QString &path)
{
    return exportWithTitle([&](int w, int h) { return savePng(path, w, h); });
}

bool MonitorPlot::exportPdf(const QString &path)
{
    return exportWithTitle([&](int w, int h) { return savePdf(path, w, h); });
}

} // namespace vt::ui
