// Printable PLC sheets: the HTML carries the key facts, the CSV has one row per
// image byte, and the PDF export renders offscreen into a valid PDF with the reported page count.
#include "app/i18n/translation.h"
#include "model/fold/fold_export.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTextDocument>
#include <gtest/gtest.h>

using namespace vt::model;
using vt::dev::Language;

namespace {

FoldSheet sheet(FoldNode node, std::size_t n)
{
    FoldPlan plan = defaultFoldPlan(node, n);
    plan.title = "Line <3> & press";
    const auto s = makeFoldSheet(plan);
    EXPECT_TRUE(s.has_value());
    return s.value_or(FoldSheet{});
}

} // namespace

TEST(FoldExport, HtmlHasTheKeyFactsEscaped)
{
    const FoldSheet s = sheet(FoldNode::DmaProfibus, 3);
    const QString html = foldSheetHtml(s, Language::English);
    EXPECT_TRUE(html.contains("HCS0220.GSD"));
    EXPECT_TRUE(html.contains("CMD15 3fold 9B-I 18B-O (kons)"));
    EXPECT_TRUE(html.contains("DAT3.3L"));
    EXPECT_TRUE(html.contains("Line &lt;3&gt; &amp; press"));
    EXPECT_FALSE(html.contains("Line <3>"));
    EXPECT_TRUE(html.contains("01 03 0F 00 03 E8 00 00")); // example telegram
    // The product number is missing: the finding is on the sheet.
    EXPECT_TRUE(html.contains("hcs0ea7.gsd"));
    const auto german = vt::i18n::Translation::load("de"); // the sheet's words through tr()
    ASSERT_TRUE(german);
    german->install();
    const QString de = foldSheetHtml(s, Language::German);
    EXPECT_TRUE(de.contains("Ausgangsabbild"));
    EXPECT_TRUE(de.contains("lang=\"de\""));

    QTextDocument doc;
    doc.setHtml(html);
    const QString text = doc.toPlainText();
    EXPECT_TRUE(text.contains("CMD15 3fold 9B-I 18B-O (kons)"));
    EXPECT_TRUE(text.contains("Line <3> & press"));
}

TEST(FoldExport, CsvHasOneRowPerImageByte)
{
    const FoldSheet s = sheet(FoldNode::Opat, 4);
    const QString csv = foldSheetCsv(s, Language::English);
    const QStringList lines = csv.split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 1 + 23 + 9); // header + OPAT master + 3 slaves (23 out) + 9 in
    EXPECT_EQ(lines[0], "direction;byte;module;sadr;field;meaning");
    EXPECT_TRUE(lines[4].startsWith("out;3;1;0;DAT0.1;")) << lines[4].toStdString();
    EXPECT_TRUE(lines[24].startsWith("in;0;;;TADR;")) << lines[24].toStdString();
}

TEST(FoldExport, PdfRendersOffscreen)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath("plan.pdf");
    const FoldSheet s = sheet(FoldNode::Opat, 8);
    const auto pages = writeFoldSheetPdf(s, Language::English, path);
    ASSERT_TRUE(pages.has_value());
    EXPECT_GT(*pages, 0);
    ::testing::Test::RecordProperty("pages", *pages);

    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray pdf = file.readAll();
    EXPECT_TRUE(pdf.startsWith("%PDF-"));
    EXPECT_TRUE(pdf.trimmed().endsWith("%%EOF"));
    // Page objects ("/Type /Page", not "/Pages") match the count the export reports.
    const QRegularExpression pageObject(QStringLiteral("/Type\\s*/Page(?![s\\w])"));
    int found = 0;
    for (auto it = pageObject.globalMatch(QString::fromLatin1(pdf)); it.hasNext(); it.next())
        ++found;
    EXPECT_EQ(found, *pages);
    // Eight modules' byte maps do not fit one A4 page.
    EXPECT_GT(*pages, 1);

    EXPECT_FALSE(
        writeFoldSheetPdf(s, Language::English, dir.filePath("no/such/dir/x.pdf")).has_value());
}

TEST(FoldExport, ImpossiblePlanHasNoSheet)
{
    PlcText why;
    EXPECT_FALSE(makeFoldSheet(defaultFoldPlan(FoldNode::DmaProfinet, 6), &why).has_value());
    EXPECT_FALSE(plcText(why, Language::English).isEmpty());
}
