#include "reference_drift_view.h"

#include "bode_plot.h"
#include "dict/cooking.h"
#include "model/text_language.h"
#include "model/tuning/drift_texts.h"
#include "response_plot.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace vt::ui {

namespace {

QString num(double v, int decimals)
{
    return std::isfinite(v) ? QLocale().toString(v, 'f', decimals) : QStringLiteral("–");
}

QTableWidget *table(QWidget *parent)
{
    auto *t = new QTableWidget(parent);
    t->verticalHeader()->setVisible(false);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

QTableWidgetItem *cell(const QString &text, bool number)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    if (number)
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

// A change with its sign, one decimal; never "-0.0".
QString signedNumber(double v)
{
    const double rounded = std::round(v * 10) / 10;
    if (rounded == 0)
        return QLocale().toString(0.0, 'f', 1);
    return (rounded > 0 ? QStringLiteral("+") : QString()) + QLocale().toString(rounded, 'f', 1);
}

// Decimals a figure is shown with.
int decimalsOf(model::DriftMetric m)
{
    switch (m) {
    case model::DriftMetric::Overshoot: return 1;
    case model::DriftMetric::Bandwidth:
    case model::DriftMetric::Phase90: return 2;
    default: return 3;
    }
}

} // namespace

ReferenceDriftView::ReferenceDriftView(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    auto *split = new QSplitter(Qt::Horizontal, this);
    auto *tables = new QSplitter(Qt::Vertical, split);
    m_metrics = table(tables);
    m_params = table(tables);
    auto *plotSide = new QWidget(split);
    auto *plotLayout = new QVBoxLayout(plotSide);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    m_plotChoice = new QComboBox(plotSide);
    plotLayout->addWidget(m_plotChoice);
    m_plots = new QStackedWidget(plotSide);
    m_response = new ResponsePlot(m_plots);
    m_bode = new BodePlot(m_plots);
    m_plots->addWidget(m_response);
    m_plots->addWidget(m_bode);
    plotLayout->addWidget(m_plots, 1);
    // The plot as wide as the tables: the overlay is what a person looks at first.
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 1);
    split->setSizes({660, 340});
    layout->addWidget(split, 1);
    connect(m_plotChoice, &QComboBox::currentIndexChanged, this, &ReferenceDriftView::showPlot);
    retranslate();
}

void ReferenceDriftView::show(const model::Reference &reference,
                              const std::vector<std::shared_ptr<model::TuningRun>> &now,
                              const std::optional<model::ReferenceComparison> &comparison)
{
    m_reference = reference;
    m_now = now;
    m_comparison = comparison;
    fill();
}

void ReferenceDriftView::clear()
{
    m_reference = {};
    m_now.clear();
    m_comparison.reset();
    fill();
}

void ReferenceDriftView::fill()
{
    const dev::Language lang = model::textLanguage();
    const model::ReferenceFileData &f = m_reference.file;
    // The summary.
    if (m_reference.runs.empty()) {
        m_summary->setText(tr("No reference yet: save one, or compare the module with one."));
    } else if (!m_comparison) {
        m_summary->setText(tr("Reference of module %1 (%2, software %3, mode %4), %5 settings.")
                               .arg(f.address)
                               .arg(QString::fromStdString(f.family),
                                    QString::fromStdString(f.version),
                                    QString::fromStdString(f.mode))
                               .arg(f.settings.size()));
    } else {
        int exceeded = 0;
        for (const model::MetricDrift &d : m_comparison->metrics)
            exceeded += d.exceeded ? 1 : 0;
        m_summary->setText((exceeded > 0 ? tr("%1 of %2 figures drifted beyond their thresholds.")
                                               .arg(exceeded)
                                               .arg(m_comparison->metrics.size())
                                         : tr("All %1 figures are within their thresholds.")
                                               .arg(m_comparison->metrics.size())) +
                           QLatin1Char(' ') +
                           tr("%n setting(s) differ from the reference.", nullptr,
                              static_cast<int>(m_comparison->params.size())));
    }

    // The figures: the reference's own, or the drift.
    m_metrics->clear();
    const QStringList heads = {tr("Test"), tr("Figure"),         tr("Reference"),
                               tr("Now"),  tr("Change (limit)"), tr("Verdict")};
    m_metrics->setColumnCount(m_comparison ? static_cast<int>(heads.size()) : 3);
    m_metrics->setHorizontalHeaderLabels(m_comparison ? heads : heads.mid(0, 3));
    if (m_comparison) {
        m_metrics->setRowCount(static_cast<int>(m_comparison->metrics.size()));
        int r = 0;
        for (const model::MetricDrift &d : m_comparison->metrics) {
            const int dec = decimalsOf(d.metric);
            const QString unit = QString::fromStdString(d.unit);
            const bool points = d.metric == model::DriftMetric::Overshoot;
            const QString change =
                std::isfinite(d.deltaPercent)
                    ? (points ? tr("%1 points") : tr("%1 %")).arg(signedNumber(d.deltaPercent))
                    : QStringLiteral("–");
            const QString sign = points ? QStringLiteral("+") : QStringLiteral("±");
            const QString threshold =
                (points ? tr("%1%2 points") : tr("%1%2 %"))
                    .arg(sign, QLocale().toString(d.thresholdPercent, 'f', 1)) +
                (d.metric == model::DriftMetric::SteadyStateError ? tr(" of the step") : QString());
            const QStringList cells = {model::DriftTexts::test(d.test),
                                       model::DriftTexts::metric(d.metric),
                                       tr("%1 %2").arg(num(d.reference, dec), unit),
                                       tr("%1 %2").arg(num(d.now, dec), unit),
                                       tr("%1 (%2)").arg(change, threshold),
                                       d.exceeded ? tr("exceeded") : tr("ok")};
            for (int c = 0; c < cells.size(); ++c)
                m_metrics->setItem(r, c, cell(cells[c], c >= 2 && c <= 4));
            m_metrics->item(r, 5)->setForeground(d.exceeded ? QColor(200, 0, 0)
                                                            : QColor(0, 130, 0));
            ++r;
        }
    } else {
        m_metrics->setRowCount(static_cast<int>(f.figures.size()));
        int r = 0;
        for (const model::ReferenceFigure &g : f.figures) {
            const auto metric = [&] {
                for (auto m :
                     {model::DriftMetric::RiseTime, model::DriftMetric::Overshoot,
                      model::DriftMetric::SettlingTime, model::DriftMetric::SteadyStateError,
                      model::DriftMetric::Bandwidth, model::DriftMetric::Phase90})
                    if (model::driftMetricKey(m) == g.metric)
                        return m;
                return model::DriftMetric::RiseTime;
            }();
            m_metrics->setItem(r, 0, cell(model::DriftTexts::test(g.test), false));
            m_metrics->setItem(r, 1, cell(model::DriftTexts::metric(metric), false));
            m_metrics->setItem(r, 2,
                               cell(tr("%1 %2").arg(num(g.value, decimalsOf(metric)),
                                                    QString::fromStdString(g.unit)),
                                    true));
            ++r;
        }
    }

    // The settings that differ.
    m_params->clear();
    m_params->setColumnCount(4);
    m_params->setHorizontalHeaderLabels({tr("Parameter"), tr("Reference"), tr("Now"), tr("Unit")});
    const std::vector<model::ParamDrift> none;
    const auto &params = m_comparison ? m_comparison->params : none;
    m_params->setRowCount(static_cast<int>(params.size()));
    const dev::Dictionary *dict =
        m_reference.runs.empty() ? nullptr : m_reference.runs.front()->dictionary;
    int r = 0;
    for (const model::ParamDrift &p : params) {
        const dev::ParamMeta *row = dict ? dict->find(p.row) : nullptr;
        const auto text = [&](const std::optional<double> &raw) {
            if (!raw)
                return tr("not read");
            if (!row)
                return QLocale().toString(*raw);
            return QString::fromStdString(row->enums.empty() ? dev::formatNumber(*row, *raw, lang)
                                                             : dev::formatValue(*row, *raw, lang));
        };
        const QString label = row ? QString::fromStdString(row->label.in(lang)) : QString();
        const QString name = label.isEmpty()
                                 ? QString::fromStdString(p.row)
                                 : tr("%1 (%2)").arg(QString::fromStdString(p.row), label);
        const QStringList cells = {name, text(p.referenceRaw), text(p.nowRaw),
                                   QString::fromStdString(p.unit)};
        for (int c = 0; c < cells.size(); ++c)
            m_params->setItem(r, c, cell(cells[c], c == 1 || c == 2));
        ++r;
    }

    // The plot choice: the steps and the sweep, as far as they were run.
    const QSignalBlocker block(m_plotChoice);
    m_plotChoice->clear();
    for (std::size_t i = 0; i < m_reference.runs.size(); ++i)
        m_plotChoice->addItem(
            model::DriftTexts::test(i < f.tests.size() ? f.tests[i].key : std::string("steps")),
            static_cast<int>(i));
    m_plotChoice->setVisible(m_plotChoice->count() > 1);
    showPlot();
}

void ReferenceDriftView::showPlot()
{
    const int i = m_plotChoice->currentIndex();
    if (i < 0 || i >= static_cast<int>(m_reference.runs.size())) {
        m_response->showRuns({});
        m_plots->setCurrentWidget(m_response);
        return;
    }
    const auto index = static_cast<std::size_t>(i);
    std::vector<const model::TuningRun *> runs;
    QStringList names;
    if (index < m_now.size()) {
        runs.push_back(m_now[index].get());
        names << tr("now");
    }
    runs.push_back(m_reference.runs[index].get());
    names << tr("reference");
    if (m_reference.runs[index]->spec.kind == model::SignalKind::Sweep) {
        m_bode->showRuns(runs, names);
        m_plots->setCurrentWidget(m_bode);
    } else {
        m_response->showRuns(runs, names);
        m_plots->setCurrentWidget(m_response);
    }
}

void ReferenceDriftView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ReferenceDriftView::retranslate()
{
    fill();
}

} // namespace vt::ui
