// LCurvePlot: the L-block curves of an LCurveTableModel drawn with QCustomPlot; points are
// dragged with the mouse, clamped to their range and between their neighbours' x, fixed
// coordinates stay put, and the finished drag goes to the model as one edit.
#pragma once

#include "model/curve/lcurve_table_model.h"

#include <QPointer>
#include <optional>
#include <qcustomplot.h>
#include <vector>

namespace vt::ui {

class LCurvePlot : public QCustomPlot
{
    Q_OBJECT
public:
    explicit LCurvePlot(QWidget *parent = nullptr);

    // Not owned (the parameter document's); a destroyed model leaves the plot empty.
    void setModel(model::LCurveTableModel *model);
    model::LCurveTableModel *model() const { return m_model; }

    // The graph of curve `curve` (points with both coordinates known, in point order).
    QCPGraph *curveGraph(int curve) const;
    bool dragging() const { return m_drag.has_value(); }

    // Pixels around a point that still grab it.
    static constexpr double kPickRadiusPx = 10;

    // The curve whose point wins where points of both branches lie on the same pixel: the one
    // selected in the table or grabbed last (the first curve until then).
    void setPreferredCurve(int curve) { m_preferredCurve = curve; }
    int preferredCurve() const { return m_preferredCurve; }

signals:
    // The user grabbed a point (the editor selects it in the table).
    void pointPicked(int curve, int index);

protected:
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Drag
    {
        int curve = 0;
        int index = 0;
        double startX = 0, startY = 0;
        double x = 0, y = 0;
        QPointF pressPos;
        bool moved = false; // past the start-drag distance: a click alone edits nothing
    };
    struct Pick
    {
        int curve = 0;
        int index = 0;
    };

    void rebuild();     // curves changed: graphs and axis ranges
    void refreshData(); // values changed
    void retranslate();
    std::optional<Pick> pickAt(const QPointF &pos) const;
    void dragTo(const QPointF &pos);
    void finishDrag();

    QPointer<model::LCurveTableModel> m_model;
    std::vector<QCPGraph *> m_graphs; // owned by the plot
    QCPGraph *m_linear = nullptr;     // the identity line, for reference
    std::optional<Drag> m_drag;
    int m_preferredCurve = 0;
};

} // namespace vt::ui
