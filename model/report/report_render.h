// The commissioning report rendered: JSON (stable keys, raw values beside the texts), a
// self-contained HTML page (plots as PNG data URIs) and an A4 PDF by Qt's own writer
// (QTextDocument on a QPdfWriter; table header rows repeat on every page, a row is never split,
// "Page n of m" in the footer). docs/REPORT.md describes the contents.
// The words come from the catalogue in force (tr(), context vt::model::Report): install the
// report's language before rendering. Numbers and dictionary texts follow report.lang. Plots and
// the PDF need a QGuiApplication; GUI thread.
#pragma once

#include "model/report/report.h"

#include <QImage>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

class QPagedPaintDevice;
class QTextDocument;

namespace vt::model {

enum class ReportFormat { Pdf, Html, Json };

// By the file name's suffix (.pdf, .html/.htm, .json); nullopt for anything else.
std::optional<ReportFormat> reportFormatOf(const QString &path);

// A plot of the report: a run's step response or Bode plot (gain, phase), or a drift overlay.
struct ReportFigure
{
    QString id;     // "run-0-response", "drift-1"; unique in the report
    int run = -1;   // index in Report::runs, or -1
    int drift = -1; // index in ReportDrift::curves, or -1
    QImage image;
};
std::vector<ReportFigure> reportFigures(const Report &report);

std::string reportJson(const Report &report);
// `source(figure)` gives the <img src> (a data URI, or a QTextDocument resource name).
QString reportHtml(const Report &report, const std::vector<ReportFigure> &figures,
                   const std::function<QString(const ReportFigure &)> &source);
// The self-contained page: figures embedded as PNG data URIs.
QString reportHtml(const Report &report);

// The report laid out for `device` (its resolution and page), figures as resources.
void fillReportDocument(QTextDocument &doc, const Report &report, QPagedPaintDevice &device);
// Paints `doc` onto `device` page by page with the footer "Page n of m"; the page count.
int paintReportPages(QTextDocument &doc, QPagedPaintDevice &device, const Report &report);
// A4 PDF at `path`: the page count, or nullopt when the file could not be written.
std::optional<int> writeReportPdf(const Report &report, const QString &path);

// Writes the report in the format its name asks for; nullopt on success, else why.
std::optional<QString> writeReport(const Report &report, const QString &path);

} // namespace vt::model
