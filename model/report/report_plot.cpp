#include "report_plot.h"

#include "model/number_text.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vt::model {

namespace {

constexpr int kWidth = 1600;
constexpr int kHeight = 640;

struct Range
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();

    void add(double v)
    {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    bool valid() const { return lo <= hi; }
};

// A 1-2-5 step giving about `count` intervals over the span.
double niceStep(double span, int count)
{
    const double raw = span / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= raw)
            return m * power;
    return 10 * power;
}

int decimalsFor(double step)
{
    return step >= 1 ? 0 : std::min(6, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
}

} // namespace

QImage renderPlot(const PlotSpec &spec, dev::Language lang)
{
    QImage image(kWidth, kHeight, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(24);
    p.setFont(font);
    const QFontMetrics fm(font);

    Range xr, yr;
    for (const PlotSeries &s : spec.series) {
        for (double x : s.x)
            xr.add(spec.logX ? (x > 0 ? std::log10(x) : NAN) : x);
        for (double y : s.y)
            yr.add(y);
    }
    if (!xr.valid())
        xr = Range{0, 1};
    if (!yr.valid())
        yr = Range{0, 1};
    if (xr.hi - xr.lo < 1e-12)
        xr = Range{xr.lo - 0.5, xr.hi + 0.5};
    const double yPad = std::max((yr.hi - yr.lo) * 0.08, std::abs(yr.hi) * 1e-3 + 1e-9);
    yr = Range{yr.lo - yPad, yr.hi + yPad};

    const QRect area(140, 100, kWidth - 180, kHeight - 200);
    const auto px = [&](double x) {
        const double v = spec.logX ? std::log10(x) : x;
        return area.left() + (v - xr.lo) / (xr.hi - xr.lo) * area.width();
    };
    const auto py = [&](double y) {
        return area.bottom() - (y - yr.lo) / (yr.hi - yr.lo) * area.height();
    };

    p.setPen(Qt::black);
    p.drawText(QRect(0, 8, kWidth, 44), Qt::AlignCenter, spec.title);

    // Grid and ticks.
    const QPen grid(QColor(220, 220, 220), 1);
    const double yStep = niceStep(yr.hi - yr.lo, 6);
    for (double y = std::ceil(yr.lo / yStep) * yStep; y <= yr.hi; y += yStep) {
        const double v = std::abs(y) < yStep * 1e-9 ? 0.0 : y;
        p.setPen(grid);
        p.drawLine(QPointF(area.left(), py(v)), QPointF(area.right(), py(v)));
        p.setPen(Qt::black);
        p.drawText(QRectF(0, py(v) - 15, area.left() - 10, 30), Qt::AlignRight | Qt::AlignVCenter,
                   formatNumber(v, decimalsFor(yStep), lang));
    }
    std::vector<double> xTicks;
    if (spec.logX) {
        for (double e = std::floor(xr.lo); e <= xr.hi; ++e)
            for (double m : {1.0, 2.0, 5.0})
                if (const double v = std::log10(m) + e; v >= xr.lo && v <= xr.hi)
                    xTicks.push_back(std::pow(10.0, v));
    } else {
        const double step = niceStep(xr.hi - xr.lo, 8);
        for (double x = std::ceil(xr.lo / step) * step; x <= xr.hi; x += step)
            xTicks.push_back(std::abs(x) < step * 1e-9 ? 0.0 : x);
    }
    for (double x : xTicks) {
        p.setPen(grid);
        p.drawLine(QPointF(px(x), area.top()), QPointF(px(x), area.bottom()));
        p.setPen(Qt::black);
        const int decimals = spec.logX ? std::max(0, -static_cast<int>(std::floor(std::log10(x))))
                                       : decimalsFor(niceStep(xr.hi - xr.lo, 8));
        p.drawText(QRectF(px(x) - 80, area.bottom() + 6, 160, 30), Qt::AlignCenter,
                   formatNumber(x, decimals, lang));
    }
    p.setPen(QPen(Qt::black, 2));
    p.drawRect(area);
    p.drawText(QRect(area.left(), area.bottom() + 40, area.width(), 40), Qt::AlignCenter,
               spec.xLabel);
    p.save();
    p.translate(30, area.center().y());
    p.rotate(-90);
    p.drawText(QRect(-area.height() / 2, -20, area.height(), 40), Qt::AlignCenter, spec.yLabel);
    p.restore();

    // Series, clipped to the plot area.
    p.setClipRect(area);
    for (const PlotSeries &s : spec.series) {
        QPen pen(s.color, 3);
        if (s.dashed)
            pen.setStyle(Qt::DashLine);
        p.setPen(pen);
        QPainterPath path;
        bool open = false;
        double lastY = 0;
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.y[i]) || (spec.logX && s.x[i] <= 0)) {
                open = false;
                continue;
            }
            const QPointF point(px(s.x[i]), py(s.y[i]));
            if (!open) {
                path.moveTo(point);
            } else {
                if (s.stairs)
                    path.lineTo(QPointF(point.x(), lastY));
                path.lineTo(point);
            }
            lastY = point.y();
            open = true;
        }
        p.drawPath(path);
    }
    p.setClipping(false);

    // Legend above the plot area, right-aligned.
    int x = area.right();
    for (auto it = spec.series.rbegin(); it != spec.series.rend(); ++it) {
        const int w = fm.horizontalAdvance(it->name) + 60;
        x -= w;
        QPen pen(it->color, 3);
        if (it->dashed)
            pen.setStyle(Qt::DashLine);
        p.setPen(pen);
        p.drawLine(x, area.top() - 14, x + 40, area.top() - 14);
        p.setPen(Qt::black);
        p.drawText(QRect(x + 46, area.top() - 30, w - 46, 30), Qt::AlignLeft | Qt::AlignVCenter,
                   it->name);
    }
    return image;
}

} // namespace vt::model
