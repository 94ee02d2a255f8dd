#include "run_results_tabs.h"

#include "dict/cooking.h"
#include "model/text_language.h"
#include "model/tuning/analysis_texts.h"

#include <QEvent>
#include <QHeaderView>
#include <QLocale>
#include <QTableWidget>
#include <cmath>

namespace vt::ui {

namespace {

QString num(double v, int decimals)
{
    return std::isfinite(v) ? QLocale().toString(v, 'f', decimals) : QStringLiteral("–");
}

void setRow(QTableWidget *table, int row, const QStringList &cells)
{
    for (int c = 0; c < cells.size(); ++c) {
        auto *item = new QTableWidgetItem(cells[c]);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        if (c > 0)
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table->setItem(row, c, item);
    }
}

} // namespace

RunResultsTabs::RunResultsTabs(QWidget *parent) : QTabWidget(parent)
{
    m_results = new QTableWidget(this);
    m_differences = new QTableWidget(this);
    for (QTableWidget *t : {m_results, m_differences}) {
        t->verticalHeader()->setVisible(false);
        t->setEditTriggers(QAbstractItemView::NoEditTriggers);
        t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        t->setMinimumHeight(60);
    }
    addTab(m_results, QString());
    addTab(m_differences, QString());
    retranslate();
}

void RunResultsTabs::showRuns(const std::vector<const model::TuningRun *> &runs)
{
    if (runs.empty())
        return;
    fillResults(*runs.front());
    fillDifferences(runs);
}

void RunResultsTabs::fillResults(const model::TuningRun &run)
{
    m_results->clear();
    const model::RunAnalysis &a = run.analysis;
    const QString unit =
        run.setValueRow ? QString::fromStdString(run.setValueRow->unit) : QString();
    if (!a.hasResponse) {
        m_results->setRowCount(0);
        m_results->setColumnCount(1);
        m_results->setHorizontalHeaderLabels(
            {tr("No response row was recorded: nothing to analyse.")});
        return;
    }
    if (!a.points.empty() && run.spec.kind != model::SignalKind::Square) {
        m_results->setColumnCount(5);
        m_results->setHorizontalHeaderLabels(
            {tr("Frequency (Hz)"), tr("Gain (dB)"), tr("Phase (°)"), tr("Quality"), tr("Valid")});
        m_results->setRowCount(static_cast<int>(a.points.size()) + 2);
        int r = 0;
        for (const model::FrequencyPoint &p : a.points)
            setRow(m_results, r++,
                   {num(p.frequencyHz, 3), num(p.gainDb, 2), num(p.phaseDeg, 1), num(p.quality, 3),
                    p.valid ? tr("yes") : model::frequencyProblemText(p.problem)});
        setRow(m_results, r++,
               {tr("−3 dB at"), a.f3dB ? num(*a.f3dB, 2) + tr(" Hz") : tr("not reached")});
        setRow(m_results, r++,
               {tr("−90° at"), a.f90deg ? num(*a.f90deg, 2) + tr(" Hz") : tr("not reached")});
        return;
    }
    m_results->setColumnCount(9);
    m_results->setHorizontalHeaderLabels(
        {tr("Step (%1)").arg(unit), tr("Dead time (s)"), tr("Rise time (s)"), tr("Overshoot (%)"),
         tr("Peak time (s)"), tr("Settling 2 % (s)"), tr("Settling 5 % (s)"),
         tr("Steady-state error (%1)").arg(unit), tr("Final value")});
    m_results->setRowCount(static_cast<int>(a.steps.size()));
    int r = 0;
    for (const model::StepResult &s : a.steps) {
        const QString step = tr("%1 → %2").arg(num(s.edge.from, 3), num(s.edge.to, 3));
        if (!s.metrics) {
            setRow(m_results, r++,
                   {step, s.problem ? model::stepProblemText(*s.problem) : QString()});
            continue;
        }
        const model::StepMetrics &m = *s.metrics;
        setRow(m_results, r++,
               {step, num(m.deadTime, 3), num(m.riseTime, 3), num(m.overshootPct, 1),
                num(m.peakTime, 3), num(m.settlingTime2, 3), num(m.settlingTime5, 3),
                num(m.steadyStateError, 3), num(m.finalValue, 3)});
    }
}

void RunResultsTabs::fillDifferences(const std::vector<const model::TuningRun *> &runs)
{
    m_differences->clear();
    m_differences->setColumnCount(3);
    if (runs.size() < 2) {
        m_differences->setRowCount(0);
        m_differences->setHorizontalHeaderLabels(
            {tr("Tick a second run to compare its settings"), QString(), QString()});
        return;
    }
    const model::TuningRun &a = *runs[0];
    const model::TuningRun &b = *runs[1];
    m_differences->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Run %1").arg(a.number), tr("Run %1").arg(b.number)});
    const auto diffs = model::settingDifferences(a, b);
    m_differences->setRowCount(static_cast<int>(diffs.size()));
    const auto text = [](const model::TuningRun &run, const std::string &name,
                         const std::optional<double> &raw) {
        if (!raw)
            return tr("not read");
        const dev::ParamMeta *row = run.dictionary ? run.dictionary->find(name) : nullptr;
        return row ? QString::fromStdString(dev::formatValue(*row, *raw, model::textLanguage()))
                   : QString::number(*raw);
    };
    int r = 0;
    for (const model::SettingDifference &d : diffs)
        setRow(m_differences, r++,
               {QString::fromStdString(d.name), text(a, d.name, d.a), text(b, d.name, d.b)});
}

void RunResultsTabs::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTabWidget::changeEvent(event);
}

void RunResultsTabs::retranslate()
{
    setTabText(0, tr("Results"));
    setTabText(1, tr("Setting differences"));
}

} // namespace vt::ui
