#include "fold_export.h"

#include "core/hex.h"

#include <QAbstractTextDocumentLayout>
#include <QCoreApplication>
#include <QFile>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>

namespace vt::model {

using dev::Language;
using dev::LocalText;

namespace {

// The sheet's own words; the plan's {en, de} texts are shown in the sheet's language.
struct FoldHtml
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::FoldSheetHtml)
};

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

QString esc(const std::string &s)
{
    return q(s).toHtmlEscaped();
}

QString bitList(const std::array<dev::hcs::BitMeaning, 8> &bits, Language lang)
{
    QStringList parts;
    for (const auto &bit : bits)
        if (bit.used)
            parts << QStringLiteral("<b>0x%1 %2</b> %3")
                         .arg(QString::number(bit.mask, 16)
                                  .toUpper()
                                  .rightJustified(2, QLatin1Char('0')),
                              esc(std::string(bit.name)), esc(bit.text.in(lang)));
    return parts.isEmpty() ? QStringLiteral("–") : parts.join(QStringLiteral("<br>"));
}

QString csvField(const QString &s)
{
    if (!s.contains(QLatin1Char(';')) && !s.contains(QLatin1Char('"')) &&
        !s.contains(QLatin1Char('\n')))
        return s;
    QString quoted = s;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

} // namespace

std::optional<FoldSheet> makeFoldSheet(const FoldPlan &plan, PlcText *why)
{
    auto config = buildPlcConfig(plan);
    if (!config.ok()) {
        if (why)
            *why = config.error();
        return std::nullopt;
    }
    return FoldSheet{plan, *config, checkFoldPlan(plan)};
}

QString foldSheetHtml(const FoldSheet &sheet, Language lang)
{
    const PlcConfig &c = sheet.config;
    QString h;
    h += QStringLiteral("<!DOCTYPE html>\n<html lang=\"%1\"><head><meta charset=\"utf-8\">\n")
             .arg(lang == Language::German ? QStringLiteral("de") : QStringLiteral("en"));
    h += QStringLiteral("<title>%1</title>\n").arg(FoldHtml::tr("PLC configuration"));
    h += QStringLiteral(
        "<style>body{font-family:sans-serif;font-size:10pt}"
        "table{border-collapse:collapse;margin-bottom:8pt}"
        "td,th{border:1px solid #888;padding:2px 6px;vertical-align:top;text-align:left}"
        "th{background:#ddd}.error{color:#a00}.warning{color:#a60}"
        "code{font-family:monospace}</style></head><body>\n");
    h += QStringLiteral("<h1>%1</h1>\n").arg(FoldHtml::tr("PLC configuration of the fold"));
    if (!sheet.plan.title.empty())
        h += QStringLiteral("<h2>%1</h2>\n").arg(esc(sheet.plan.title));

    h += QStringLiteral("<table>\n");
    const auto row = [&h](const QString &k, const QString &v) {
        h += QStringLiteral("<tr><th>%1</th><td>%2</td></tr>\n").arg(k, v);
    };
    row(FoldHtml::tr("Node"), foldNodeTitle(c.node).toHtmlEscaped() + QStringLiteral(" (") +
                                  esc(std::string(foldNodeKey(c.node))) + QStringLiteral(")"));
    row(FoldHtml::tr("Modules"), QString::number(c.modules));
    if (!sheet.plan.productNumber.empty())
        row(FoldHtml::tr("Product number"), esc(sheet.plan.productNumber));
    row(FoldHtml::tr("GSD file"), QStringLiteral("<code>%1</code>").arg(esc(c.gsdFile)));
    row(FoldHtml::tr("Catalogue device"), esc(c.gsdDevice));
    row(FoldHtml::tr("GSD module"), QStringLiteral("<b>%1</b>").arg(esc(c.gsdModule)));
    row(FoldHtml::tr("Output (PLC → node)"),
        FoldHtml::tr("%1 bytes, SNUM = %2").arg(c.outputBytes).arg(c.snum));
    row(FoldHtml::tr("Input (node → PLC)"),
        FoldHtml::tr("%1 bytes, one module per answer").arg(c.inputBytes));
    row(FoldHtml::tr("Reserved by the GSD module"), FoldHtml::tr("%1 bytes out / %2 bytes in")
                                                        .arg(c.moduleOutputBytes)
                                                        .arg(c.moduleInputBytes));
    row(FoldHtml::tr("Source"), plcText(c.gsdNote, lang).toHtmlEscaped());
    h += QStringLiteral("</table>\n");

    h +=
        QStringLiteral(
            "<h2>%1</h2>\n<table><tr><th>#</th><th>%2</th><th>%3</th><th>%4</th><th>%5</th></tr>\n")
            .arg(FoldHtml::tr("Modules and addresses"), FoldHtml::tr("Address"),
                 FoldHtml::tr("Software / mode"), FoldHtml::tr("Name"), FoldHtml::tr("Options"));
    for (std::size_t i = 0; i < sheet.plan.modules.size(); ++i) {
        const FoldModule &m = sheet.plan.modules[i];
        QStringList options;
        for (const std::string &name : foldOptionNames(c.node, i))
            if (const auto v = foldOption(m.options, name))
                options << QStringLiteral("%1 = %2").arg(q(name)).arg(*v);
        const QString sw =
            (m.version ? QStringLiteral("V%1").arg(m.version) : QStringLiteral("V?")) +
            QStringLiteral(" / ") + (m.mode ? QString::number(m.mode) : QStringLiteral("?"));
        h += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>\n")
                 .arg(i + 1)
                 .arg(foldAddressText(c.node, m).toHtmlEscaped(), sw, esc(m.name),
                      options.isEmpty() ? QStringLiteral("–") : options.join(QStringLiteral(", ")));
    }
    h += QStringLiteral("</table>\n");

    if (!sheet.findings.empty()) {
        h += QStringLiteral("<h2>%1</h2>\n<ul>\n").arg(FoldHtml::tr("Check"));
        for (const FoldFinding &f : sheet.findings)
            h += QStringLiteral("<li class=\"%1\"><b>%2</b>: %3</li>\n")
                     .arg(q(std::string(foldSeverityKey(f.severity))),
                          foldSeverityText(f.severity).toHtmlEscaped(),
                          foldFindingText(f).toHtmlEscaped());
        h += QStringLiteral("</ul>\n");
    }

    const auto imageTable = [&](const std::vector<PlcImageByte> &bytes, const QString &title) {
        h += QStringLiteral(
                 "<h2>%1</h2>\n<table><tr><th>%2</th><th>%3</th><th>%4</th><th>%5</th></tr>\n")
                 .arg(title, FoldHtml::tr("Byte"), FoldHtml::tr("Module"), FoldHtml::tr("Field"),
                      FoldHtml::tr("Meaning"));
        for (const PlcImageByte &b : bytes)
            h += QStringLiteral(
                     "<tr><td>%1</td><td>%2</td><td><code>%3</code></td><td>%4</td></tr>\n")
                     .arg(b.offset)
                     .arg(b.module < 0 ? QStringLiteral("–") : QString::number(b.module + 1),
                          esc(b.field), plcText(b.text, lang).toHtmlEscaped());
        h += QStringLiteral("</table>\n");
    };
    imageTable(c.output, FoldHtml::tr("Output image (PLC → node, CMD 15 request)"));
    imageTable(c.input,
               FoldHtml::tr("Input image (node → PLC, multiplexed: SADR names the module)"));

    h +=
        QStringLiteral("<h2>%1</h2>\n<p>%2</p>\n<table><tr><th>%3</th><th>%4</th><th>%5</"
                       "th><th>%6</th><th>%7</th></tr>\n")
            .arg(
                FoldHtml::tr("Bits per module"),
                FoldHtml::tr(
                    "Only the bits of each module's own mode apply (DMA Profibus Anleitung §6, DMA "
                    "Profinet manual §5)."),
                FoldHtml::tr("Module / SADR"), FoldHtml::tr("Layout"), FoldHtml::tr("Control byte"),
                FoldHtml::tr("Status high byte"), FoldHtml::tr("Status low byte"));
    for (const PlcModuleSection &s : c.sections) {
        const auto &info = dev::hcs::profileInfo(s.profile);
        const QString layout =
            esc(info.title.in(lang)) + QStringLiteral("<br>VALUE1 → ") +
            esc(std::string(info.response1.parameter) + " " + info.response1.text.in(lang)) +
            QStringLiteral("<br>VALUE2 → ") +
            esc(std::string(info.response2.parameter) + " " + info.response2.text.in(lang)) +
            QStringLiteral("<br><i>%1</i>").arg(esc(std::string(info.source)));
        h += QStringLiteral(
                 "<tr><td>%1 / %2</td><td>%3</td><td>%4</td><td>%5</td><td>%6</td></tr>\n")
                 .arg(s.module + 1)
                 .arg(s.sadr)
                 .arg(layout, bitList(s.controlBits, lang), bitList(s.statusHighBits, lang),
                      bitList(s.statusLowBits, lang));
    }
    h += QStringLiteral("</table>\n");

    h += QStringLiteral("<h2>%1</h2>\n<p>%2</p>\n<p><code>%3</code></p>\n")
             .arg(FoldHtml::tr("Example CMD 15 telegram"),
                  FoldHtml::tr(
                      "TADR 0x01, control byte 0x00, VALUE1 = 1000 (1.000 V), VALUE2 = 0 for every "
                      "module."),
                  esc(dev::toHex(c.exampleRequestBytes)));
    h += QStringLiteral("<p><small>%1: %2</small></p>\n")
             .arg(FoldHtml::tr("Sources"), esc(c.source));
    h += QStringLiteral("</body></html>\n");
    return h;
}

QString foldSheetCsv(const FoldSheet &sheet, Language lang)
{
    const PlcConfig &c = sheet.config;
    QString out = QStringLiteral("direction;byte;module;sadr;field;meaning\n");
    const auto rows = [&](const std::vector<PlcImageByte> &bytes, const QString &dir) {
        for (const PlcImageByte &b : bytes) {
            QString sadr;
            if (b.module >= 0 && b.module < static_cast<int>(c.sections.size()))
                sadr = QString::number(c.sections[static_cast<std::size_t>(b.module)].sadr);
            out += dir + QLatin1Char(';') + QString::number(b.offset) + QLatin1Char(';') +
                   (b.module < 0 ? QString() : QString::number(b.module + 1)) + QLatin1Char(';') +
                   sadr + QLatin1Char(';') + csvField(q(b.field)) + QLatin1Char(';') +
                   csvField(plcText(b.text, lang)) + QLatin1Char('\n');
        }
    };
    rows(c.output, QStringLiteral("out"));
    rows(c.input, QStringLiteral("in"));
    return out;
}

std::optional<int> writeFoldSheetPdf(const FoldSheet &sheet, Language lang, const QString &path)
{
    {
        // QPdfWriter reports no open failure; find out first.
        QFile probe(path);
        if (!probe.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return std::nullopt;
    }
    QPdfWriter writer(path);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setTitle(QStringLiteral("ValveTune fold plan"));
    writer.setCreator(QStringLiteral("ValveTune"));

    QTextDocument doc;
    // Lay the document out for the writer (its resolution, its page) so that point sizes come out
    // as points on paper and pageCount() is the printed page count.
    doc.documentLayout()->setPaintDevice(&writer);
    doc.setHtml(foldSheetHtml(sheet, lang));
    doc.setPageSize(writer.pageLayout().paintRectPixels(writer.resolution()).size());
    doc.print(&writer);
    const int pages = doc.pageCount();
    if (QFile(path).size() <= 0)
        return std::nullopt;
    return pages;
}

} // namespace vt::model
