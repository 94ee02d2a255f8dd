#include "report_text.h"

#include "model/number_text.h"
#include "model/params/parameter_tree_model.h"
#include "model/session/write_record.h"
#include "model/tuning/analysis_texts.h"

#include <QLocale>
#include <cmath>

namespace vt::model {

QString reportQs(const std::string &text)
{
    return QString::fromStdString(text);
}

QString reportNumber(double value, int decimals, dev::Language lang)
{
    return std::isfinite(value) ? formatNumber(value, decimals, lang) : QStringLiteral("–");
}

QString reportDateTime(const QDateTime &time, dev::Language lang)
{
    return time.toString(lang == dev::Language::German ? QStringLiteral("dd.MM.yyyy HH:mm:ss")
                                                       : QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

QString reportValueText(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    return formatRaw(row, value, lang);
}

QString reportDefaultText(const dev::ParamMeta &row, dev::Language lang)
{
    return row.defaultValue && !row.isString() ? formatRaw(row, *row.defaultValue, lang)
                                               : QString();
}

QString reportModuleTitle(const ReportModule &module, dev::Language lang)
{
    const QString device = module.dictionary ? reportQs(module.dictionary->title.in(lang))
                                             : ReportText::tr("unknown device");
    if (module.mode.empty())
        return ReportText::tr("Module %1 · %2, software %3")
            .arg(module.address)
            .arg(device, reportQs(module.version));
    return ReportText::tr("Module %1 · %2, software %3, mode %4")
        .arg(module.address)
        .arg(device, reportQs(module.version), reportQs(module.mode));
}

QString reportWriteStatusText(const QString &key)
{
    for (const WriteStatus status :
         {WriteStatus::Pending, WriteStatus::Unchanged, WriteStatus::RefusedLocally,
          WriteStatus::Verified, WriteStatus::Written, WriteStatus::Refused, WriteStatus::Mismatch,
          WriteStatus::Uncertain, WriteStatus::NotSent})
        if (key == QLatin1String(writeStatusKey(status)))
            return writeStatusText(status);
    return key;
}

QString reportWriteReason(const ReportWrite &write, dev::Language lang)
{
    return lang == dev::Language::German && !write.reasonDe.isEmpty() ? write.reasonDe
                                                                      : write.reasonEn;
}

QStringList reportStepColumns(const TuningRun &run)
{
    const QString unit = run.setValueRow ? reportQs(run.setValueRow->unit) : QString();
    return {ReportText::tr("Step"),
            ReportText::tr("Set value (%1)").arg(unit),
            ReportText::tr("Dead time (s)"),
            ReportText::tr("Rise time (s)"),
            ReportText::tr("Overshoot (%)"),
            ReportText::tr("Settling ±2 % (s)"),
            ReportText::tr("Settling ±5 % (s)"),
            ReportText::tr("Steady-state error (%1)").arg(unit)};
}

QStringList reportStepCells(const TuningRun &run, const StepResult &step, dev::Language lang)
{
    const int decimals = run.setValueRow ? run.setValueRow->scale.decimals : 3;
    const QString direction =
        step.edge.to >= step.edge.from ? ReportText::tr("up") : ReportText::tr("down");
    QStringList cells{direction,
                      ReportText::tr("%1 → %2").arg(reportNumber(step.edge.from, decimals, lang),
                                                    reportNumber(step.edge.to, decimals, lang))};
    if (!step.metrics) {
        cells << (step.problem ? stepProblemText(*step.problem) : QString());
        return cells;
    }
    const StepMetrics &m = *step.metrics;
    cells << reportNumber(m.deadTime, 3, lang) << reportNumber(m.riseTime, 3, lang)
          << reportNumber(m.overshootPct, 1, lang) << reportNumber(m.settlingTime2, 3, lang)
          << reportNumber(m.settlingTime5, 3, lang)
          << reportNumber(m.steadyStateError, decimals, lang);
    return cells;
}

} // namespace vt::model
