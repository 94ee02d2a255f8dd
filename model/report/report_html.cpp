// The report as HTML: one page, inline CSS within what QTextDocument understands (the PDF is the
// same HTML laid out by QTextDocument), tables with <thead> so their header row repeats on every
// printed page.
#include "model/fold/plc_config.h"
#include "model/params/parameter_tree_model.h"
#include "model/tuning/analysis_texts.h"
#include "report_render.h"
#include "report_text.h"

#include <QBuffer>

namespace vt::model {

namespace {

using dev::Language;

QString esc(const QString &text)
{
    return text.toHtmlEscaped();
}

QString esc(const std::string &text)
{
    return reportQs(text).toHtmlEscaped();
}

QString cell(const QString &text, const char *tag = "td", const QString &attributes = {})
{
    return QStringLiteral("<%1%2>%3</%1>")
        .arg(QLatin1String(tag), attributes.isEmpty() ? QString() : QLatin1Char(' ') + attributes,
             text.isEmpty() ? QStringLiteral("&nbsp;") : text);
}

// A table whose header row repeats on every page; cells are HTML already.
QString table(const QStringList &head, const std::vector<QStringList> &rows,
              const std::vector<bool> &marked = {}, const std::vector<int> &widths = {})
{
    QString html = QStringLiteral("<table class=\"grid\" width=\"100%\" border=\"1\" "
                                  "cellspacing=\"0\" cellpadding=\"3\"><thead><tr>");
    for (qsizetype i = 0; i < head.size(); ++i) {
        const auto c = static_cast<std::size_t>(i);
        html += cell(
            esc(head[i]), "th",
            QStringLiteral("bgcolor=\"#e4e8ee\" align=\"left\"") +
                (c < widths.size() ? QStringLiteral(" width=\"%1%\"").arg(widths[c]) : QString()));
    }
    html += QStringLiteral("</tr></thead><tbody>");
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const bool mark = r < marked.size() && marked[r];
        html += QStringLiteral("<tr>");
        for (const QString &c : rows[r])
            html += cell(c, "td", mark ? QStringLiteral("bgcolor=\"#fff1c2\"") : QString());
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</tbody></table>");
}

// Two columns of label and value, no header.
QString pairs(const std::vector<std::pair<QString, QString>> &rows)
{
    QString html = QStringLiteral(
        "<table class=\"pairs\" width=\"100%\" border=\"0\" cellspacing=\"0\" cellpadding=\"2\">");
    for (const auto &[label, value] : rows)
        html += QStringLiteral("<tr><td width=\"28%\"><b>%1</b></td><td>%2</td></tr>")
                    .arg(esc(label), value.isEmpty() ? QStringLiteral("&nbsp;") : esc(value));
    return html + QStringLiteral("</table>");
}

QString headerSection(const Report &r)
{
    const Language lang = r.lang;
    std::vector<std::pair<QString, QString>> rows = {
        {ReportText::tr("Customer"), r.header.customer},
        {ReportText::tr("Machine"), r.header.machine},
        {ReportText::tr("Axis"), r.header.axis},
        {ReportText::tr("Operator"), r.header.operatorName},
        {ReportText::tr("Comment"), r.header.comment},
        {ReportText::tr("Date and time"), reportDateTime(r.created, lang)},
        {ReportText::tr("ValveTune version"), r.toolVersion},
    };
    if (!r.connection.isEmpty())
        rows.emplace_back(ReportText::tr("Connection"), r.connection);
    if (!r.sourceFile.isEmpty())
        rows.emplace_back(ReportText::tr("Parameter file (offline)"), r.sourceFile);
    rows.emplace_back(ReportText::tr("Reference file"),
                      r.referenceFile.isEmpty() ? ReportText::tr("none") : r.referenceFile);
    return QStringLiteral("<h1>%1</h1>").arg(esc(ReportText::tr("Commissioning report"))) +
           pairs(rows);
}

QString modulesSection(const Report &r)
{
    const Language lang = r.lang;
    std::vector<QStringList> rows;
    for (const ReportModule &m : r.modules) {
        int fromDefault = 0, fromReference = 0;
        for (const ReportSetting &s : m.settings) {
            fromDefault += s.differsFromDefault();
            fromReference += s.differsFromReference();
        }
        rows.push_back({QString::number(m.address),
                        m.dictionary ? esc(m.dictionary->title.in(lang)) + QStringLiteral("<br>") +
                                           esc(m.dictionary->family)
                                     : esc(ReportText::tr("unknown device")),
                        esc(m.version),
                        esc(m.mode.empty() ? QStringLiteral("–") : reportQs(m.mode)),
                        esc(m.identity.in(lang)), QString::number(m.settings.size()),
                        QString::number(fromDefault),
                        r.referenceFile.isEmpty() ? QStringLiteral("–")
                        : m.inReference           ? QString::number(fromReference)
                                                  : esc(ReportText::tr("not in the reference"))});
    }
    return QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Modules"))) +
           table({ReportText::tr("Address"), ReportText::tr("Device"), ReportText::tr("Software"),
                  ReportText::tr("Mode"), ReportText::tr("Type code / serial"),
                  ReportText::tr("Settings"), ReportText::tr("Not default"),
                  ReportText::tr("Differ from reference")},
                 rows, {}, {10, 23, 10, 7, 15, 11, 11, 13});
}

// The longest parameter name of the module, in characters: HCS names are 4–5 ("C1.07"), Wandfluh
// names up to about 30 ("vprc_TrailingWindowDelayTime"), which must not wrap.
qsizetype nameWidth(const ReportModule &m)
{
    qsizetype width = 0;
    for (const ReportSetting &s : m.settings)
        width = std::max(width, static_cast<qsizetype>(s.row->name.size()));
    return width;
}

QString settingsSection(const Report &r, const ReportModule &m)
{
    const Language lang = r.lang;
    static const std::vector<int> widthsShort{11, 25, 16, 18, 16, 14};
    static const std::vector<int> widthsLong{33, 20, 13, 14, 11, 9};
    std::vector<QStringList> rows;
    std::vector<bool> marked;
    for (const ReportSetting &s : m.settings) {
        QStringList marks;
        if (s.differsFromDefault())
            marks << esc(ReportText::tr("≠ default"));
        if (s.differsFromReference())
            marks << esc(
                ReportText::tr("≠ reference: %1").arg(reportValueText(*s.row, *s.reference, lang)));
        rows.push_back({QStringLiteral("<b>%1</b>").arg(esc(s.row->name)),
                        esc(s.row->label.in(lang)), esc(reportValueText(*s.row, s.value, lang)),
                        esc(ParameterTreeModel::rangeText(*s.row, lang)),
                        esc(reportDefaultText(*s.row, lang)), marks.join(QStringLiteral("<br>"))});
        marked.push_back(!marks.isEmpty());
    }
    QString html = QStringLiteral("<h2>%1</h2>").arg(esc(reportModuleTitle(m, lang)));
    if (!m.label.empty())
        html += QStringLiteral("<p>%1</p>").arg(esc(m.label));
    if (!m.identity.in(lang).empty())
        html += QStringLiteral("<p>%1</p>").arg(esc(m.identity.in(lang)));
    if (rows.empty())
        return html + QStringLiteral("<p>%1</p>")
                          .arg(esc(ReportText::tr("No settings known for this module.")));
    return html +
           table({ReportText::tr("Parameter"), ReportText::tr("Name"), ReportText::tr("Value"),
                  ReportText::tr("Range"), ReportText::tr("Default"), ReportText::tr("Marks")},
                 rows, marked, nameWidth(m) > 9 ? widthsLong : widthsShort);
}

QString writesSection(const Report &r)
{
    QString html = QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Write log")));
    if (r.writes.empty())
        return html + QStringLiteral("<p>%1</p>").arg(esc(ReportText::tr("No writes recorded.")));
    std::vector<QStringList> rows;
    std::vector<bool> marked;
    for (const ReportWrite &w : r.writes) {
        const QString reason = reportWriteReason(w, r.lang);
        QString status = esc(reportWriteStatusText(w.status));
        if (!reason.isEmpty())
            status += QStringLiteral("<br>") + esc(reason);
        rows.push_back({esc(reportDateTime(w.time, r.lang)), QString::number(w.module),
                        QStringLiteral("<b>%1</b> %2").arg(esc(w.row), esc(w.name)),
                        esc(ReportText::tr("%1 → %2").arg(w.oldText, w.newText)), status});
        marked.push_back(w.status != QLatin1String("verified") &&
                         w.status != QLatin1String("unchanged"));
    }
    return html +
           table({ReportText::tr("Time"), ReportText::tr("Module"), ReportText::tr("Parameter"),
                  ReportText::tr("Old → new"), ReportText::tr("Result")},
                 rows, marked);
}

QString image(const std::vector<ReportFigure> &figures,
              const std::function<QString(const ReportFigure &)> &source, const QString &id)
{
    for (const ReportFigure &f : figures)
        if (f.id == id)
            return QStringLiteral("<p><img src=\"%1\" width=\"640\" height=\"%2\"></p>")
                .arg(source(f).toHtmlEscaped())
                .arg(640 * f.image.height() / std::max(1, f.image.width()));
    return {};
}

QString runsSection(const Report &r, const std::vector<ReportFigure> &figures,
                    const std::function<QString(const ReportFigure &)> &source)
{
    const Language lang = r.lang;
    QString html = QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Workbench runs")));
    if (r.runs.empty())
        return html + QStringLiteral("<p>%1</p>")
                          .arg(esc(ReportText::tr("No workbench runs chosen for the report.")));
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
        const TuningRun &run = r.runs[i];
        const QString prefix = QStringLiteral("run-%1-").arg(i);
        html += QStringLiteral("<h3>%1</h3>").arg(esc(runTitle(run)));
        html += QStringLiteral("<p>%1</p>")
                    .arg(esc(ReportText::tr("Started %1; %2 set-value writes.")
                                 .arg(reportDateTime(run.started, lang))
                                 .arg(run.recording.writes)));
        if (!run.analysis.steps.empty()) {
            std::vector<QStringList> rows;
            for (const StepResult &step : run.analysis.steps) {
                QStringList cells;
                for (const QString &c : reportStepCells(run, step, lang))
                    cells << esc(c);
                rows.push_back(cells);
            }
            html += table(reportStepColumns(run), rows);
        }
        html += image(figures, source, prefix + QStringLiteral("response"));
        if (!run.analysis.points.empty()) {
            std::vector<QStringList> rows;
            for (const FrequencyPoint &p : run.analysis.points)
                rows.push_back(
                    {esc(reportNumber(p.frequencyHz, 3, lang)),
                     esc(reportNumber(p.gainDb, 2, lang)), esc(reportNumber(p.phaseDeg, 1, lang)),
                     p.valid ? esc(ReportText::tr("yes")) : esc(frequencyProblemText(p.problem))});
            html += table({ReportText::tr("Frequency (Hz)"), ReportText::tr("Gain (dB)"),
                           ReportText::tr("Phase (°)"), ReportText::tr("Valid")},
                          rows);
            const auto hz = [&](const std::optional<double> &f) {
                return f ? ReportText::tr("%1 Hz").arg(reportNumber(*f, 2, lang))
                         : ReportText::tr("not reached");
            };
            html += QStringLiteral("<p>%1</p>")
                        .arg(esc(ReportText::tr("−3 dB at %1, −90° at %2.")
                                     .arg(hz(run.analysis.f3dB), hz(run.analysis.f90deg))));
            html += image(figures, source, prefix + QStringLiteral("gain"));
            html += image(figures, source, prefix + QStringLiteral("phase"));
        }
    }
    return html;
}

QString foldSection(const Report &r)
{
    if (!r.fold)
        return {};
    const PlcConfig &c = r.fold->config;
    QString html =
        QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Fold / PLC configuration")));
    html += pairs({{ReportText::tr("Node"), foldNodeTitle(c.node)},
                   {ReportText::tr("GSD file"), reportQs(c.gsdFile)},
                   {ReportText::tr("GSD device"), reportQs(c.gsdDevice)},
                   {ReportText::tr("GSD module"), reportQs(c.gsdModule)},
                   {ReportText::tr("Output bytes (PLC → node)"), QString::number(c.outputBytes)},
                   {ReportText::tr("Input bytes (node → PLC)"), QString::number(c.inputBytes)}});
    std::vector<QStringList> rows;
    for (const PlcModuleSection &s : c.sections) {
        const FoldModule &m = r.fold->plan.modules[static_cast<std::size_t>(s.module)];
        rows.push_back(
            {QString::number(s.module + 1), QString::number(m.address), QString::number(s.sadr),
             ReportText::tr("%1 … %2").arg(s.outputFirst).arg(s.outputFirst + s.outputLength - 1),
             esc(std::string(dev::hcs::profileInfo(s.profile).key))});
    }
    return html +
           table({ReportText::tr("Module"), ReportText::tr("Address"), ReportText::tr("SADR"),
                  ReportText::tr("Output bytes"), ReportText::tr("Layout")},
                 rows);
}

QString driftSection(const Report &r, const std::vector<ReportFigure> &figures,
                     const std::function<QString(const ReportFigure &)> &source)
{
    const ReportDrift &d = r.drift;
    if (d.empty())
        return {};
    const Language lang = r.lang;
    QString html =
        QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Drift against the reference")));
    html += pairs({{ReportText::tr("Reference fingerprint"), d.referenceFile},
                   {ReportText::tr("Taken"), reportDateTime(d.takenAt, lang)}});
    html += QStringLiteral("<h3>%1</h3>").arg(esc(ReportText::tr("Parameter differences")));
    if (d.params.empty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(ReportText::tr("none")));
    } else {
        std::vector<QStringList> rows;
        for (const ReportDriftParam &p : d.params)
            rows.push_back({QString::number(p.module),
                            QStringLiteral("<b>%1</b> %2").arg(esc(p.row), esc(p.name)),
                            esc(p.reference), esc(p.now), esc(p.unit)});
        html += table({ReportText::tr("Module"), ReportText::tr("Parameter"),
                       ReportText::tr("Reference"), ReportText::tr("Now"), ReportText::tr("Unit")},
                      rows);
    }
    html += QStringLiteral("<h3>%1</h3>").arg(esc(ReportText::tr("Step figures")));
    if (d.metrics.empty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(ReportText::tr("none")));
    } else {
        std::vector<QStringList> rows;
        std::vector<bool> marked;
        for (const ReportDriftMetric &m : d.metrics) {
            rows.push_back(
                {QString::number(m.module), esc(m.test), esc(m.metric),
                 esc(reportNumber(m.reference, 3, lang) + QLatin1Char(' ') + m.unit),
                 esc(reportNumber(m.now, 3, lang) + QLatin1Char(' ') + m.unit),
                 esc(ReportText::tr("%1 %").arg(reportNumber(m.deltaPercent, 1, lang))),
                 esc(ReportText::tr("± %1 %").arg(reportNumber(m.thresholdPercent, 1, lang))),
                 m.exceeded ? esc(ReportText::tr("exceeded")) : QString()});
            marked.push_back(m.exceeded);
        }
        html += table({ReportText::tr("Module"), ReportText::tr("Test"), ReportText::tr("Figure"),
                       ReportText::tr("Reference"), ReportText::tr("Now"), ReportText::tr("Change"),
                       ReportText::tr("Threshold"), ReportText::tr("Verdict")},
                      rows, marked);
    }
    for (std::size_t i = 0; i < d.curves.size(); ++i)
        html += image(figures, source, QStringLiteral("drift-%1").arg(i));
    return html;
}

QString signatureSection()
{
    const QString line = QStringLiteral("<br><br><br>________________________________");
    return QStringLiteral("<h2>%1</h2>").arg(esc(ReportText::tr("Signatures"))) +
           QStringLiteral("<table width=\"100%\" border=\"0\" cellpadding=\"6\"><tr>"
                          "<td width=\"50%\">%1<br>%2</td><td width=\"50%\">%3<br>%4</td>"
                          "</tr></table>")
               .arg(line, esc(ReportText::tr("Commissioned by (date, name, signature)")), line,
                    esc(ReportText::tr("Accepted by the customer (date, name, signature)")));
}

} // namespace

QString reportHtml(const Report &report, const std::vector<ReportFigure> &figures,
                   const std::function<QString(const ReportFigure &)> &source)
{
    QString html =
        QStringLiteral(
            "<!DOCTYPE html><html lang=\"%1\"><head><meta charset=\"utf-8\"><title>%2</title>"
            "<style>body { font-family: 'DejaVu Sans', Arial, sans-serif; font-size: 9pt; }"
            " h1 { font-size: 16pt; } h2 { font-size: 12pt; margin-top: 14px; }"
            " h3 { font-size: 10pt; }"
            " table.grid { border-collapse: collapse; font-size: 8pt; margin-bottom: 6px; }"
            " table.grid th, table.grid td { border: 1px solid #9aa3ad; vertical-align: top; }"
            "</style></head><body>")
            .arg(report.lang == Language::German ? QStringLiteral("de") : QStringLiteral("en"),
                 esc(ReportText::tr("Commissioning report")));
    html += headerSection(report);
    html += modulesSection(report);
    for (const ReportModule &m : report.modules)
        html += settingsSection(report, m);
    html += writesSection(report);
    html += runsSection(report, figures, source);
    html += foldSection(report);
    html += driftSection(report, figures, source);
    html += signatureSection();
    return html + QStringLiteral("</body></html>");
}

QString reportHtml(const Report &report)
{
    return reportHtml(report, reportFigures(report), [](const ReportFigure &f) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        f.image.save(&buffer, "PNG");
        return QStringLiteral("data:image/png;base64,") + QString::fromLatin1(png.toBase64());
    });
}

} // namespace vt::model
