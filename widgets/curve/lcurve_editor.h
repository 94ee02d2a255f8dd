// LCurveEditor: the linearisation (L block) page — the curves as a plot with draggable points
// beside the same points as a table, both views of one LCurveTableModel, and a line saying why
// the last edit was refused. Undo belongs to the document that owns the model.
#pragma once

#include <QWidget>

class QLabel;
class QTableView;

namespace vt::model {
class LCurveTableModel;
}

namespace vt::ui {

class LCurvePlot;

class LCurveEditor : public QWidget
{
    Q_OBJECT
public:
    explicit LCurveEditor(QWidget *parent = nullptr);

    // Not owned. nullptr empties both views.
    void setModel(model::LCurveTableModel *model);

    LCurvePlot *plot() const { return m_plot; }
    QTableView *table() const { return m_table; }
    // The refusal shown under the views ("L1.x3 must be below L1.x4 (5.000 V)"), empty if none.
    QString message() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void showRefusal(int curve, int index, const QString &reason);

    LCurvePlot *m_plot = nullptr;
    QTableView *m_table = nullptr;
    QLabel *m_hint = nullptr;
    QLabel *m_message = nullptr;
    model::LCurveTableModel *m_model = nullptr;
};

} // namespace vt::ui
