#include "lcurve_plot.h"

#include "model/curve/lcurve_table_model.h"

#include <QApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <cmath>
#include <limits>

namespace vt::ui {
namespace {

const QColor kCurveColours[] = {QColor(31, 119, 180), QColor(214, 95, 0)};

QString fromStd(const std::string &s)
{
    return QString::fromStdString(s);
}

} // namespace

LCurvePlot::LCurvePlot(QWidget *parent) : QCustomPlot(parent)
{
    setMouseTracking(true);          // hover cursor over draggable points
    setFocusPolicy(Qt::StrongFocus); // Esc cancels a drag
    legend->setVisible(true);
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    setMinimumSize(320, 240);
    retranslate();
}

void LCurvePlot::setModel(model::LCurveTableModel *model)
{
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    m_drag.reset();
    if (m_model) {
        connect(m_model, &QAbstractItemModel::modelReset, this, &LCurvePlot::rebuild);
        connect(m_model, &QAbstractItemModel::dataChanged, this, &LCurvePlot::refreshData);
        connect(m_model, &QObject::destroyed, this, &LCurvePlot::rebuild);
    }
    rebuild();
}

QCPGraph *LCurvePlot::curveGraph(int curve) const
{
    return curve >= 0 && curve < static_cast<int>(m_graphs.size())
               ? m_graphs[static_cast<std::size_t>(curve)]
               : nullptr;
}

void LCurvePlot::rebuild()
{
    m_drag.reset();
    clearGraphs();
    m_graphs.clear();
    m_linear = nullptr;
    if (!m_model || m_model->curves().empty()) {
        replot(rpQueuedReplot);
        return;
    }
    double xMin = std::numeric_limits<double>::max(), xMax = std::numeric_limits<double>::lowest();
    double yMin = xMin, yMax = xMax;
    for (const model::LCurve &c : m_model->curves()) {
        for (const model::LPoint &p : c.points) {
            xMin = std::min(xMin, p.x.min);
            xMax = std::max(xMax, p.x.max);
            yMin = std::min(yMin, p.y.min);
            yMax = std::max(yMax, p.y.max);
        }
    }
    m_linear = addGraph();
    m_linear->setPen(QPen(Qt::gray, 1, Qt::DashLine));
    m_linear->setData({xMin, xMax}, {xMin, xMax}, true);
    m_linear->removeFromLegend();
    m_linear->setSelectable(QCP::stNone);

    for (std::size_t i = 0; i < m_model->curves().size(); ++i) {
        QCPGraph *g = addGraph();
        const QColor colour = kCurveColours[i % std::size(kCurveColours)];
        g->setPen(QPen(colour, 2));
        g->setScatterStyle(
            QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(colour, 2), QBrush(Qt::white), 9));
        g->setSelectable(QCP::stNone);
        m_graphs.push_back(g);
    }
    const double xPad = (xMax - xMin) * 0.03, yPad = (yMax - yMin) * 0.03;
    xAxis->setRange(xMin - xPad, xMax + xPad);
    yAxis->setRange(yMin - yPad, yMax + yPad);
    retranslate();
    refreshData();
}

void LCurvePlot::refreshData()
{
    if (!m_model)
        return;
    for (std::size_t c = 0; c < m_graphs.size(); ++c) {
        const auto curve = static_cast<int>(c);
        const auto &values = m_model->values(curve);
        QVector<double> keys, vals;
        for (std::size_t i = 0; i < values.size(); ++i) {
            double x = values[i].x.value_or(std::nan("")), y = values[i].y.value_or(std::nan(""));
            if (m_drag && m_drag->curve == curve && m_drag->index == static_cast<int>(i)) {
                x = m_drag->x;
                y = m_drag->y;
            }
            if (std::isnan(x) || std::isnan(y))
                continue;
            keys.push_back(x);
            vals.push_back(y);
        }
        // Points stay in x order while dragged, but values read from a device need not be.
        m_graphs[c]->setData(keys, vals, false);
    }
    replot(rpQueuedReplot);
}

void LCurvePlot::retranslate()
{
    QString unit;
    if (m_model && !m_model->curves().empty())
        unit = fromStd(m_model->curves().front().unit);
    setLocale(QLocale()); // tick labels in the UI language's notation ("2,5")
    xAxis->setLabel(unit.isEmpty() ? tr("Input (set value)")
                                   : tr("Input (set value) / %1").arg(unit));
    yAxis->setLabel(unit.isEmpty() ? tr("Output") : tr("Output / %1").arg(unit));
    if (m_model) {
        for (std::size_t i = 0; i < m_graphs.size() && i < m_model->curves().size(); ++i) {
            const model::LCurve &c = m_model->curves()[i];
            m_graphs[i]->setName(tr("Branch %1 (%2)").arg(c.branch).arg(fromStd(c.name)));
        }
    }
    replot(rpQueuedReplot);
}

std::optional<LCurvePlot::Pick> LCurvePlot::pickAt(const QPointF &pos) const
{
    if (!m_model)
        return std::nullopt;
    // The nearest point; points closer to each other than a pixel (the branches' curves
    // overlap) go to the preferred curve.
    constexpr double kSamePixel = 1.0;
    std::optional<Pick> best;
    double bestDistance = kPickRadiusPx;
    for (std::size_t c = 0; c < m_model->curves().size(); ++c) {
        const model::LCurve &curve = m_model->curves()[c];
        const auto &values = m_model->values(static_cast<int>(c));
        for (std::size_t i = 0; i < curve.points.size() && i < values.size(); ++i) {
            if (!values[i].x || !values[i].y ||
                (curve.points[i].x.fixed() && curve.points[i].y.fixed()))
                continue;
            const double dx = xAxis->coordToPixel(*values[i].x) - pos.x();
            const double dy = yAxis->coordToPixel(*values[i].y) - pos.y();
            const double d = std::hypot(dx, dy);
            const bool tie = best && std::abs(d - bestDistance) < kSamePixel;
            const bool wins =
                tie ? static_cast<int>(c) == m_preferredCurve && best->curve != m_preferredCurve
                    : d <= bestDistance;
            if (wins) {
                bestDistance = d;
                best = Pick{static_cast<int>(c), static_cast<int>(i)};
            }
        }
    }
    return best;
}

void LCurvePlot::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && !m_drag) {
        if (const auto pick = pickAt(event->position())) {
            const double x = *m_model->value(pick->curve, pick->index, model::LAxis::X);
            const double y = *m_model->value(pick->curve, pick->index, model::LAxis::Y);
            m_drag = Drag{pick->curve, pick->index, x, y, x, y, event->position(), false};
            m_preferredCurve = pick->curve;
            setCursor(Qt::ClosedHandCursor);
            emit pointPicked(pick->curve, pick->index);
            event->accept();
            return;
        }
    }
    QCustomPlot::mousePressEvent(event);
}

void LCurvePlot::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag) {
        dragTo(event->position());
        event->accept();
        return;
    }
    if (pickAt(event->position()))
        setCursor(Qt::OpenHandCursor);
    else
        unsetCursor();
    QCustomPlot::mouseMoveEvent(event);
}

void LCurvePlot::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_drag && event->button() == Qt::LeftButton) {
        dragTo(event->position());
        finishDrag();
        event->accept();
        return;
    }
    QCustomPlot::mouseReleaseEvent(event);
}

void LCurvePlot::keyPressEvent(QKeyEvent *event)
{
    if (m_drag && event->key() == Qt::Key_Escape) {
        m_drag.reset();
        unsetCursor();
        refreshData();
        event->accept();
        return;
    }
    QCustomPlot::keyPressEvent(event);
}

void LCurvePlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QCustomPlot::changeEvent(event);
}

void LCurvePlot::dragTo(const QPointF &pos)
{
    if (!m_model || !m_drag)
        return;
    if (!m_drag->moved &&
        (pos - m_drag->pressPos).manhattanLength() < QApplication::startDragDistance())
        return;
    m_drag->moved = true;
    const model::LPoint &point = m_model->curves()[static_cast<std::size_t>(m_drag->curve)]
                                     .points[static_cast<std::size_t>(m_drag->index)];
    const auto follow = [&](model::LAxis axis, double wanted, double start) {
        const model::LCoordinate &coord = model::coordinate(point, axis);
        const model::LRange range = m_model->allowedRange(m_drag->curve, m_drag->index, axis);
        if (coord.fixed() || range.empty())
            return start;
        return model::snapToStep(coord, range.clamp(wanted));
    };
    m_drag->x = follow(model::LAxis::X, xAxis->pixelToCoord(pos.x()), m_drag->startX);
    m_drag->y = follow(model::LAxis::Y, yAxis->pixelToCoord(pos.y()), m_drag->startY);
    refreshData();
}

void LCurvePlot::finishDrag()
{
    const Drag drag = *m_drag;
    m_drag.reset();
    unsetCursor();
    const bool movedX = drag.x != drag.startX, movedY = drag.y != drag.startY;
    if (m_model && (movedX || movedY)) {
        // One edit per completed drag, so the document records one undo step.
        m_model->editPoint(drag.curve, drag.index, movedX ? std::optional(drag.x) : std::nullopt,
                           movedY ? std::optional(drag.y) : std::nullopt);
    }
    refreshData(); // a refused edit snaps the point back
}

} // namespace vt::ui
