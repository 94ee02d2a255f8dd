#include "model/report/report_drift.h"

#include "model/params/parameter_tree_model.h"
#include "model/report/report_text.h"
#include "model/tuning/drift_texts.h"

namespace vt::model {

namespace {

// A setting's value on one side of the comparison: as the editor shows it when the row is known,
// else the number; "–" when that side does not hold it.
QString sideText(const dev::ParamMeta *row, const std::optional<double> &raw,
                 const std::optional<double> &display, dev::Language lang)
{
    if (row && raw)
        return formatRaw(*row, *raw, lang);
    if (display)
        return reportNumber(*display, 3, lang);
    return QStringLiteral("–");
}

QDateTime savedAt(const std::string &iso)
{
    const QString text = QString::fromStdString(iso);
    QDateTime time = QDateTime::fromString(text, Qt::ISODateWithMs);
    return time.isValid() ? time : QDateTime::fromString(text, Qt::ISODate);
}

} // namespace

ReportDrift reportDrift(const Reference &reference, const ReferenceComparison &comparison,
                        const QString &file, const dev::Dictionary *dictionary, dev::Language lang)
{
    ReportDrift drift;
    drift.referenceFile = file;
    drift.takenAt = savedAt(reference.file.saved);
    for (const ParamDrift &p : comparison.params) {
        const dev::ParamMeta *row = dictionary ? dictionary->find(p.row) : nullptr;
        const std::string label = row ? row->label.in(lang) : p.name;
        drift.params.push_back(
            {p.module, QString::fromStdString(p.row),
             QString::fromStdString(label.empty() ? p.name : label),
             sideText(row, p.referenceRaw, p.reference, lang), sideText(row, p.nowRaw, p.now, lang),
             row ? QString() : QString::fromStdString(p.unit)}); // the editor's text has the unit
    }
    for (const MetricDrift &m : comparison.metrics)
        drift.metrics.push_back({m.module, DriftTexts::test(m.test), DriftTexts::metric(m.metric),
                                 m.reference, m.now, QString::fromStdString(m.unit), m.deltaPercent,
                                 m.thresholdPercent, m.exceeded});
    const dev::ParamMeta *setValue =
        dictionary ? dictionary->find(reference.file.setValue) : nullptr;
    for (const DriftOverlay &o : comparison.overlays) {
        if (o.frequency)
            continue; // the report's overlay axis is time; a sweep's drift is in its figures
        drift.curves.push_back({reference.file.address, DriftTexts::test(o.test),
                                setValue ? QString::fromStdString(setValue->unit) : QString(), o.x,
                                o.reference, o.now});
    }
    return drift;
}

} // namespace vt::model
