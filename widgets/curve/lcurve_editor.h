// LCurveEditor: the linearisation (L block) page — the curves as a plot with draggable points
// beside the same points as a table, both views of one LCurveTableModel, and a line saying why
// the last edit was refused; for a module whose family has no L block, the sentence that says so
// instead. Undo belongs to the document that owns the model.
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
    // The "no linearisation curve" sentence, empty while the module has curves or none is chosen.
    QString noCurveText() const;
    // Names the module whose curves are shown (address -1: none) above the views, with its
    // parameter list's title in the UI language.
    void setModule(int address);
    QString moduleText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void showRefusal(int curve, int index, const QString &reason);
    void showWhetherCurves();

    LCurvePlot *m_plot = nullptr;
    QTableView *m_table = nullptr;
    QLabel *m_subject = nullptr;
    int m_address = -1;
    QLabel *m_hint = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_noCurve = nullptr;
    QWidget *m_views = nullptr;
    model::LCurveTableModel *m_model = nullptr;
};

} // namespace vt::ui
