// Words and numbers shared by the report's renderers (JSON carries the same texts the pages show).
// tr() context vt::model::Report; numbers in report.lang. GUI thread.
#pragma once

#include "model/report/report.h"

#include <QCoreApplication>
#include <QString>

namespace vt::model {

class ReportText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::Report)
};

QString reportQs(const std::string &text);
// A number in the language's notation with `decimals` digits; "–" when it is not finite.
QString reportNumber(double value, int decimals, dev::Language lang);
QString reportDateTime(const QDateTime &time, dev::Language lang);
QString reportValueText(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang);
// The default in display units; empty when the dictionary gives none.
QString reportDefaultText(const dev::ParamMeta &row, dev::Language lang);
// "Module 3 · DMA-2 PROFINET, software 51.02, mode 3"
QString reportModuleTitle(const ReportModule &module, dev::Language lang);
// The write's status key as words ("verified", "refused by the device"); the key when unknown.
QString reportWriteStatusText(const QString &key);
QString reportWriteReason(const ReportWrite &write, dev::Language lang);
// The step's figures as the table shows them, in the order of reportStepColumns().
QStringList reportStepColumns(const TuningRun &run);
QStringList reportStepCells(const TuningRun &run, const StepResult &step, dev::Language lang);

} // namespace vt::model
