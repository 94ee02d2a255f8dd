// ReferenceDriftView: a reference comparison as the workbench shows it (model::ReferenceComparison,
// docs/TUNING.md "Reference fingerprint") — the settings that differ (reference, now, unit), each
// figure with its change, threshold and ok / exceeded, and the old and new responses overlaid on
// the workbench's own plots (the steps on a ResponsePlot, a sweep on a BodePlot; a choice between
// them when both were run). Shows a reference alone (its runs, no comparison) after it was saved.
// Owner: the reference panel; GUI thread.
#pragma once

#include "model/tuning/reference_fingerprint.h"

#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QStackedWidget;
class QTableWidget;

namespace vt::ui {

class BodePlot;
class ResponsePlot;

class ReferenceDriftView : public QWidget
{
    Q_OBJECT
public:
    explicit ReferenceDriftView(QWidget *parent = nullptr);

    // The reference's runs and, when `comparison` is given, the runs now and the drift. The runs
    // are shared: the view keeps them as long as it shows them.
    void show(const model::Reference &reference,
              const std::vector<std::shared_ptr<model::TuningRun>> &now,
              const std::optional<model::ReferenceComparison> &comparison);
    void clear();

    QTableWidget *settingsTable() const { return m_params; }
    QTableWidget *figuresTable() const { return m_metrics; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void fill();
    void showPlot();
    void retranslate();

    model::Reference m_reference;
    std::vector<std::shared_ptr<model::TuningRun>> m_now;
    std::optional<model::ReferenceComparison> m_comparison;

    QLabel *m_summary = nullptr;
    QTableWidget *m_params = nullptr;
    QTableWidget *m_metrics = nullptr;
    QComboBox *m_plotChoice = nullptr;
    QStackedWidget *m_plots = nullptr;
    ResponsePlot *m_response = nullptr;
    BodePlot *m_bode = nullptr;
};

} // namespace vt::ui
