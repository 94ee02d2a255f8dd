// The report on paper: the HTML laid out by QTextDocument for the device's page, painted page by
// page with a footer, and the file writers by format.
#include "model/file_write.h"
#include "report_render.h"
#include "report_text.h"

#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextDocument>
#include <QUrl>

namespace vt::model {

namespace {

// Footer height in millimetres below the text area of each page.
constexpr double kFooterMm = 9;

double mmToPixels(double mm, const QPagedPaintDevice &device)
{
    return mm / 25.4 * device.logicalDpiX();
}

} // namespace

std::optional<ReportFormat> reportFormatOf(const QString &path)
{
    const QString lower = path.toLower();
    if (lower.endsWith(QLatin1String(".pdf")))
        return ReportFormat::Pdf;
    if (lower.endsWith(QLatin1String(".html")) || lower.endsWith(QLatin1String(".htm")))
        return ReportFormat::Html;
    if (lower.endsWith(QLatin1String(".json")))
        return ReportFormat::Json;
    return std::nullopt;
}

void fillReportDocument(QTextDocument &doc, const Report &report, QPagedPaintDevice &device)
{
    // Laid out for the device (its resolution): point sizes come out as points on paper.
    doc.documentLayout()->setPaintDevice(&device);
    const std::vector<ReportFigure> figures = reportFigures(report);
    for (const ReportFigure &f : figures)
        doc.addResource(QTextDocument::ImageResource, QUrl(f.id), f.image);
    doc.setHtml(reportHtml(report, figures, [](const ReportFigure &f) { return f.id; }));
}

int paintReportPages(QTextDocument &doc, QPagedPaintDevice &device, const Report &report)
{
    const QSizeF page = device.pageLayout().paintRectPixels(device.logicalDpiX()).size();
    const double footer = mmToPixels(kFooterMm, device);
    const QSizeF body(page.width(), page.height() - footer);
    doc.setPageSize(body);
    const int pages = doc.pageCount();

    QPainter painter(&device);
    QFont font = doc.defaultFont();
    font.setPointSizeF(7.5);
    painter.setFont(font);
    const QString left = ReportText::tr("Commissioning report · %1")
                             .arg(reportDateTime(report.created, report.lang));
    for (int i = 0; i < pages; ++i) {
        if (i > 0)
            device.newPage();
        painter.save();
        painter.translate(0, -i * body.height());
        doc.drawContents(&painter, QRectF(QPointF(0, i * body.height()), body));
        painter.restore();
        const QRectF foot(0, body.height() + footer * 0.25, body.width(), footer * 0.75);
        painter.setPen(QColor(90, 90, 90));
        painter.drawLine(QPointF(0, foot.top()), QPointF(body.width(), foot.top()));
        painter.drawText(foot, Qt::AlignLeft | Qt::AlignVCenter, left);
        painter.drawText(foot, Qt::AlignRight | Qt::AlignVCenter,
                         ReportText::tr("Page %1 of %2").arg(i + 1).arg(pages));
    }
    return pages;
}

std::optional<int> writeReportPdf(const Report &report, const QString &path)
{
    {
        // QPdfWriter reports no open failure; find out first.
        QFile probe(path);
        if (!probe.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return std::nullopt;
    }
    QPdfWriter writer(path);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageMargins(QMarginsF(15, 12, 15, 10), QPageLayout::Millimeter);
    writer.setResolution(300);
    writer.setTitle(ReportText::tr("Commissioning report"));
    writer.setCreator(QStringLiteral("ValveTune ") + report.toolVersion);
    QTextDocument doc;
    fillReportDocument(doc, report, writer);
    const int pages = paintReportPages(doc, writer, report);
    return pages;
}

std::optional<QString> writeReport(const Report &report, const QString &path)
{
    const auto format = reportFormatOf(path);
    if (!format)
        return ReportText::tr("%1: the report's file name must end in .pdf, .html or .json.")
            .arg(path);
    if (*format == ReportFormat::Pdf) {
        if (!writeReportPdf(report, path))
            return ReportText::tr("Cannot write %1.").arg(path);
        return std::nullopt;
    }
    const QByteArray bytes = *format == ReportFormat::Json
                                 ? QByteArray::fromStdString(reportJson(report))
                                 : reportHtml(report).toUtf8();
    if (QString why = writeFileAtomically(path, bytes); !why.isEmpty())
        return why;
    return std::nullopt;
}

} // namespace vt::model
