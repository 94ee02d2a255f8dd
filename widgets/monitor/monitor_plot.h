// MonitorPlot: the live monitor's QCustomPlot — one graph per channel read straight from the
// model's SampleStores, decimated to about one min/max pair per pixel (STYLE.md rule 10; each
// graph keeps its slices between redraws in a DecimationCache, so a plot that follows the
// newest samples reads only the rows that arrived since its last redraw), one
// value axis per unit, the tuning journal's markers on the time axis and a cursor line.
// It draws only when told (refresh()); the MonitorView coalesces. GUI thread.
#pragma once

#include "model/monitor/decimation_cache.h"
#include "model/monitor/sample_store.h"
#include "model/session/device_access.h"

#include <QDateTime>
#include <QString>
#include <functional>
#include <optional>
#include <qcustomplot.h>
#include <vector>

namespace vt::ui {

struct PlotChannel
{
    const model::SampleStore *store = nullptr; // owned by the model; must outlive setChannels()
    int column = 0;                            // the store's channel
    QString id;                                // "d1.11", or "2/d1.11" with several modules
    QString name;                              // "actual value"
    QString unit;                              // "V"
    int decimals = 3;
};

class MonitorPlot : public QCustomPlot
{
    Q_OBJECT
public:
    explicit MonitorPlot(QWidget *parent = nullptr);
    ~MonitorPlot() override;

    void setChannels(std::vector<PlotChannel> channels);
    const std::vector<PlotChannel> &channels() const { return m_channels; }
    int unitAxisCount() const { return static_cast<int>(m_unitAxes.size()); }
    QCPAxis *unitAxis(const QString &unit) const;

    // On (default): ranges wider than the plot are reduced to a min/max pair per pixel column.
    // Off: every sample goes to QCustomPlot (the benchmark's baseline).
    void setDecimation(bool on) { m_decimate = on; }
    // The next loadRange() decimates every graph from its store again, not from the slices kept
    // since the last one (the benchmark's full redraw; a new width or range start does it, too).
    void forgetDecimation();
    bool decimation() const { return m_decimate; }

    // Loads the samples of [t0, t1] into the graphs and sets the time axis to it.
    void loadRange(double t0, double t1);
    // Each value axis to its graphs' values in the time range, with a margin.
    void rescaleValueAxes();
    // Markers inside the time axis' range, as vertical lines with their text.
    void setMarkers(const std::vector<model::SampleMarker> &markers);
    // Points the graphs hold now (decimation shows here).
    qsizetype pointCount() const;
    // Replots done through refresh() (tests: no redraw while hidden).
    int replotCount() const { return m_replots; }
    // loadRange + markers (+ rescale) + replot.
    void refresh(double t0, double t1, const std::vector<model::SampleMarker> &markers,
                 bool rescale);

    // The cursor read-out: every channel's sample nearest to `t` ("t = 1.250 s", "d1.11 0.987 V").
    QStringList readout(double t) const;
    void setCursorAt(std::optional<double> t);
    std::optional<double> cursorTime() const { return m_cursorTime; }

    // Exports at the widget's size (or 1000 × 600 while it has none yet), with a title that
    // names the modules, the date and the time.
    bool exportPng(const QString &path);
    bool exportPdf(const QString &path);
    // The modules the plot shows, for the export's title.
    void setModules(const std::vector<model::ModuleInfo> &modules);
    QString exportTitle(const QDateTime &when) const;
    QString lastExportTitle() const { return m_lastExportTitle; }
    // The whole text of the journal markers within a few pixels of `pixelX` (the hover text).
    QString markerTextNear(double pixelX) const;

    // Labels follow the language (the time axis title).
    void retranslate();

signals:
    // The mouse is over the plot at time `t` (for the read-out).
    void hovered(double t);

protected:
    void mouseMoveEvent(QMouseEvent *event) override;

private:
    QCPAxis *axisFor(const QString &unit);
    void removeMarkerItems();
    QSize exportSize() const;
    bool exportWithTitle(const std::function<bool(int width, int height)> &save);

    std::vector<PlotChannel> m_channels;
    std::vector<model::DecimationCache> m_caches;          // one per graph, in m_channels' order
    std::vector<std::pair<QString, QCPAxis *>> m_unitAxes; // in order of first use
    std::vector<QCPAbstractItem *> m_markerItems;
    std::vector<model::SampleMarker> m_shownMarkers; // inside the time axis, in order
    std::vector<model::ModuleInfo> m_modules;
    QString m_lastExportTitle;
    QCPItemLine *m_cursorLine = nullptr;
    std::optional<double> m_cursorTime;
    bool m_decimate = true;
    int m_replots = 0;
    QList<double> m_times, m_values; // reused buffers
};

} // namespace vt::ui
