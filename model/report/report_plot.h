// Simple line plots for the commissioning report, drawn with QPainter into a QImage (no widget, so
// valvetune-cli draws them offscreen): a frame, ticks with numbers in the report's language, axis
// labels with units, a legend. Linear or logarithmic x axis (Bode plots). Needs a QGuiApplication
// (fonts); GUI thread.
#pragma once

#include "core/local_text.h"

#include <QColor>
#include <QImage>
#include <QString>
#include <vector>

namespace vt::model {

struct PlotSeries
{
    QString name;
    std::vector<double> x;
    std::vector<double> y; // same length as x; NaN leaves a gap
    QColor color;
    bool dashed = false;
    bool stairs = false; // held between samples (a set value as written)
};

struct PlotSpec
{
    QString title;
    QString xLabel; // with unit: "time (s)"
    QString yLabel;
    bool logX = false;
    std::vector<PlotSeries> series;
};

// 1600 × 640 pixels: sharp at 190 dpi across an A4 text column.
QImage renderPlot(const PlotSpec &spec, dev::Language lang);

} // namespace vt::model
