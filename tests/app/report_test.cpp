// The commissioning report (model/report, valvetune-cli report) for every device family, online on
// the built-in simulator and offline from a parameter file, in both languages: the JSON holds every
// setting; the PDF's page count is sane, pdftotext finds every setting's name and "Page n of m",
// and pdftoppm renders no blank page; the write log, the runs, the reference marks and the drift
// given to the report appear in its JSON and HTML. poppler-utils (scripts/deps test) reads the PDF.
#include "app/cli/exit_codes.h"
#include "cli_run.h"
#include "dict/dictionary_loader.h"
#include "model/params/param_file_io.h"
#include "model/params/parameter_tree_model.h"
#include "model/report/report_drift.h"
#include "model/report/report_render.h"
#include "model/tuning/run_file.h"
#include "widgets/report/report_dialog.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QListWidget>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <cmath>
#include <set>

namespace vt::test {
namespace {

using Json = nlohmann::json;

struct FamilyCase
{
    const char *sim;  // --sim FAMILY[:MODULES]
    const char *lang; // the report's language
    bool pdfOnline;   // the PDF from the simulator (else from the file)
};

void PrintTo(const FamilyCase &c, std::ostream *os)
{
    *os << c.sim << ' ' << c.lang;
}

QString run(const QString &program, const QStringList &args)
{
    QProcess p;
    p.start(program, args);
    EXPECT_TRUE(p.waitForFinished(30'000)) << program.toStdString();
    EXPECT_EQ(p.exitCode(), 0) << program.toStdString() << ' '
                               << p.readAllStandardError().toStdString();
    return QString::fromUtf8(p.readAllStandardOutput());
}

std::set<std::string> settingNames(const Json &report)
{
    std::set<std::string> names;
    for (const Json &m : report["modules"])
        for (const Json &s : m["settings"])
            names.insert(s["name"].get<std::string>());
    return names;
}

std::size_t settingCount(const Json &report)
{
    std::size_t n = 0;
    for (const Json &m : report["modules"])
        n += m["settings"].size();
    return n;
}

Json readJson(const QString &path)
{
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return Json::parse(f.readAll().toStdString(), nullptr, false);
}

// A page with something on it: at 30 dpi, text and table lines leave many non-white pixels.
int inkPixels(const QImage &page)
{
    int ink = 0;
    for (int y = 0; y < page.height(); ++y)
        for (int x = 0; x < page.width(); ++x)
            ink += qGray(page.pixel(x, y)) < 200;
    return ink;
}

class ReportFamilies : public ::testing::TestWithParam<FamilyCase>
{
protected:
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    QStringList sim() const { return {"--sim", QString::fromLatin1(GetParam().sim)}; }
    QStringList lang() const { return {"--lang", QString::fromLatin1(GetParam().lang)}; }
    QTemporaryDir m_dir;
};

TEST_P(ReportFamilies, OnlineAndOfflineReportsHoldEverySettingAndThePdfReads)
{
    const bool german = std::string(GetParam().lang) == "de";
    const CliRun read = cli(QStringList{"read", "--out", path("node.vtpar")} + sim());
    ASSERT_EQ(read.code, cli::kExitOk) << what(read);
    const auto file = model::readParamFile(path("node.vtpar"), dev::Language::English);
    ASSERT_TRUE(file.ok());
    std::size_t fileSettings = 0;
    for (const auto &m : file->modules)
        fileSettings += m.values.size();

    const CliRun online = cli(QStringList{"report", "--out", path("online.json")} + sim() + lang());
    ASSERT_EQ(online.code, cli::kExitOk) << what(online);
    const CliRun offline =
        cli(QStringList{"report", "--file", path("node.vtpar"), "--out", path("offline.json")} +
            lang());
    ASSERT_EQ(offline.code, cli::kExitOk) << what(offline);
    const Json a = readJson(path("online.json"));
    const Json b = readJson(path("offline.json"));
    EXPECT_EQ(a["language"], GetParam().lang);
    EXPECT_EQ(a["modules"].size(), file->modules.size());
    // Every setting the node holds (the .vtpar carries exactly the settings): the software
    // version rows of HCS modules are in both.
    EXPECT_EQ(settingCount(a), fileSettings);
    EXPECT_EQ(settingNames(a), settingNames(b));
    EXPECT_FALSE(a["connection"].get<std::string>().empty());
    EXPECT_EQ(b["file"], path("node.vtpar").toStdString());
    // Values in the report's notation: a German report has a decimal comma somewhere.
    const std::string dump = a.dump();
    if (german) {
        EXPECT_NE(dump.find(",0"), std::string::npos);
    }

    const QString pdf = path("report.pdf");
    const QStringList source =
        GetParam().pdfOnline ? sim() : QStringList{"--file", path("node.vtpar")};
    const CliRun r =
        cli(QStringList{"report", "--out", pdf, "--customer", "Kunde Ä"} + source + lang());
    ASSERT_EQ(r.code, cli::kExitOk) << what(r);
    const QString info = run(QStringLiteral("pdfinfo"), {pdf});
    const QRegularExpression pagesLine(QStringLiteral("Pages:\\s+(\\d+)"));
    const int pages = pagesLine.match(info).captured(1).toInt();
    // About 40 settings per page plus the title page's sections.
    const auto settings = static_cast<int>(fileSettings);
    EXPECT_GE(pages, 1 + settings / 60) << info.toStdString();
    EXPECT_LE(pages, 3 + settings / 25) << info.toStdString();

    // The PDF's fonts set "ff", "fi", "fl" as ligatures; NFKC gives the letters back.
    const QString text = run(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, "-"})
                             .normalized(QString::NormalizationForm_KC);
    for (const std::string &name : settingNames(a))
        EXPECT_TRUE(text.contains(QString::fromStdString(name))) << name;
    EXPECT_TRUE(text.contains(QStringLiteral("Kunde Ä")));
    const QString pageOf =
        german ? QStringLiteral("Seite %1 von %2") : QStringLiteral("Page %1 of %2");
    EXPECT_TRUE(text.contains(pageOf.arg(1).arg(pages))) << text.left(400).toStdString();
    EXPECT_TRUE(text.contains(pageOf.arg(pages).arg(pages)));
    EXPECT_TRUE(text.contains(german ? QStringLiteral("Inbetriebnahmeprotokoll")
                                     : QStringLiteral("Commissioning report")));

    run(QStringLiteral("pdftoppm"), {"-png", "-r", "30", pdf, path("page")});
    const QStringList pngs = QDir(m_dir.path()).entryList({"page*.png"}, QDir::Files, QDir::Name);
    ASSERT_EQ(pngs.size(), pages);
    for (const QString &png : pngs) {
        const QImage image(m_dir.filePath(png));
        ASSERT_FALSE(image.isNull()) << png.toStdString();
        EXPECT_GT(inkPixels(image), 300) << png.toStdString();
    }
}

INSTANTIATE_TEST_SUITE_P(EveryFamily, ReportFamilies,
                         ::testing::Values(FamilyCase{"opat:3", "de", false},
                                           FamilyCase{"dma-pn-v51", "en", true},
                                           FamilyCase{"dma-pb-v15:3", "en", false},
                                           FamilyCase{"dma-pb-v32:2", "de", true},
                                           FamilyCase{"wandfluh-ed1", "de", false},
                                           FamilyCase{"wandfluh-sd7", "en", true}),
                         [](const auto &test) {
                             std::string name = std::string(test.param.sim) + "_" + test.param.lang;
                             for (char &c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

// A step run as the workbench saves it: 3 → 5 V after 1 s, a first-order response (τ 0.1 s).
void writeStepRun(const QString &csvPath)
{
    model::RunFileData data;
    data.number = 7;
    data.started = "2026-05-02T09:30:00Z";
    data.module = 1;
    data.family = "dma-pn-v51";
    data.mode = "3";
    data.setValue = "A1.01";
    data.response = "d1.02";
    data.spec.kind = model::SignalKind::Step;
    data.spec.from = 3;
    data.spec.to = 5;
    data.spec.hold = 1;
    data.end = "finished";
    data.writes = 2;
    data.setValueSamples = {{0.0, 1.0}, {3.0, 5.0}};
    data.channelNames = {"d1.02"};
    model::Samples actual;
    for (int i = 0; i <= 400; ++i) {
        const double t = i * 0.005;
        actual.t.push_back(t);
        actual.y.push_back(t < 1 ? 3.0 : 5.0 - 2.0 * std::exp(-(t - 1) / 0.1));
    }
    data.channels = {actual};
    const auto write = [](const QString &path, const std::string &text) {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text.data(), static_cast<qint64>(text.size()));
    };
    write(csvPath, model::runCsv(data));
    QString json = csvPath;
    json.replace(QStringLiteral(".csv"), QStringLiteral(".json"));
    write(json, model::runJson(data));
}

TEST(ReportContents, WritesRunsReferenceMarksAndDriftReachJsonAndHtml)
{
    QTemporaryDir dir;
    const QString vtpar = dir.filePath(QStringLiteral("node.vtpar"));
    ASSERT_EQ(cli({"read", "--sim", "dma-pn-v51", "--out", vtpar}).code, cli::kExitOk);
    const auto &dictionaries = dev::builtinDictionaries();
    ASSERT_TRUE(dictionaries.ok());
    auto file = model::readParamFile(vtpar, dev::Language::English);
    ASSERT_TRUE(file.ok());
    // The reference differs in one setting.
    auto reference = *file;
    dev::files::ValueRow *changed = nullptr;
    for (auto &row : reference.modules[0].values)
        if (row.name == "C1.13")
            changed = &row;
    ASSERT_TRUE(changed);
    changed->raw = dev::rawNumber(changed->raw) + 10;

    const QString runPath = dir.filePath(QStringLiteral("run7.csv"));
    writeStepRun(runPath);
    QString why;
    auto stepRun = model::loadRun(runPath, *dictionaries, &why);
    ASSERT_TRUE(stepRun) << why.toStdString();

    model::ReportInput input;
    input.header.customer = QStringLiteral("ACME");
    input.settings = *file;
    input.sourceFile = vtpar;
    input.reference = reference;
    input.referenceFile = QStringLiteral("reference.vtpar");
    input.writes.push_back({QDateTime::currentDateTime(),
                            1,
                            "C1.13",
                            "P-portion KP1",
                            "V/V",
                            "1.00 V/V",
                            "2.00 V/V",
                            "verified",
                            {},
                            {}});
    input.writes.push_back({QDateTime::currentDateTime(), 1, "C1.03", "Gain A", "V/V", "1.00 V/V",
                            "9.00 V/V", "refused", "value out of range",
                            "Wert außerhalb des Bereichs"});
    input.runs.push_back(std::move(*stepRun));
    input.drift.referenceFile = QStringLiteral("fingerprint.vtref");
    input.drift.params.push_back({1, "C1.13", "P-portion KP1", "1.00", "2.00", "V/V"});
    input.drift.metrics.push_back({1, "step up", "rise time", 0.2, 0.26, "s", 30, 20, true});
    input.drift.curves.push_back({1, "step up", "V", {0, 1, 2}, {3, 4, 5}, {3, 3.8, 5}});
    const model::Report report =
        model::assembleReport(input, *dictionaries, dev::Language::English);

    const Json json = Json::parse(model::reportJson(report));
    ASSERT_EQ(json["writes"].size(), 2u);
    EXPECT_EQ(json["writes"][0]["status"], "verified");
    EXPECT_EQ(json["writes"][1]["reason"], "value out of range");
    ASSERT_EQ(json["runs"].size(), 1u);
    EXPECT_EQ(json["runs"][0]["number"], 7);
    ASSERT_EQ(json["runs"][0]["steps"].size(), 1u);
    // τ = 0.1 s: rise time 10–90 % = τ·ln 9.
    EXPECT_NEAR(json["runs"][0]["steps"][0]["rise_time_s"].get<double>(), 0.1 * std::log(9.0),
                0.01);
    std::vector<std::string> differing;
    for (const Json &s : json["modules"][0]["settings"])
        if (s["differs_from_reference"].get<bool>())
            differing.push_back(s["name"]);
    EXPECT_EQ(differing, std::vector<std::string>{"C1.13"});
    EXPECT_EQ(json["drift"]["metrics"][0]["exceeded"], true);
    EXPECT_EQ(json["fold"]["node"], "dma-pn");

    const QString html = model::reportHtml(report);
    EXPECT_TRUE(html.contains(QStringLiteral("value out of range")));
    EXPECT_TRUE(html.contains(QStringLiteral("9.00 V/V")));
    EXPECT_TRUE(html.contains(QStringLiteral("Run 7")));
    EXPECT_TRUE(html.contains(QStringLiteral("fingerprint.vtref")));
    // The run's plot and the drift overlay, embedded.
    EXPECT_EQ(html.count(QStringLiteral("src=\"data:image/png;base64,")), 2);
    for (const Json &s : json["modules"][0]["settings"])
        EXPECT_TRUE(html.contains(QString::fromStdString(s["name"].get<std::string>())));

    // Nothing given: the sections say so, the drift is left out.
    model::ReportInput bare;
    bare.settings = *file;
    const model::Report empty = model::assembleReport(bare, *dictionaries, dev::Language::English);
    const QString bareHtml = model::reportHtml(empty);
    EXPECT_TRUE(bareHtml.contains(QStringLiteral("No writes recorded.")));
    EXPECT_FALSE(bareHtml.contains(QStringLiteral("Drift")));
    EXPECT_TRUE(Json::parse(model::reportJson(empty))["drift"].is_null());
}

TEST(ReportDialogTest, SavesWhatItsMakerGivesAndRemembersTheHeader)
{
    QSettings().remove(QStringLiteral("report"));
    QTemporaryDir dir;
    const QString vtpar = dir.filePath(QStringLiteral("node.vtpar"));
    ASSERT_EQ(cli({"read", "--sim", "opat", "--out", vtpar}).code, cli::kExitOk);
    const auto file = model::readParamFile(vtpar, dev::Language::English);
    ASSERT_TRUE(file.ok());
    const auto &dictionaries = dev::builtinDictionaries();
    ui::ReportChoice seen;
    const ui::ReportMaker maker = [&](const ui::ReportChoice &choice, const auto &use) {
        seen = choice;
        model::ReportInput input;
        input.header = choice.header;
        input.settings = *file;
        use(model::assembleReport(input, *dictionaries, choice.lang));
        return QString();
    };
    {
        ui::ReportDialog dialog({QStringLiteral("Run 1 · step")}, dev::Language::German, maker);
        dialog.findChild<QLineEdit *>(QStringLiteral("reportCustomer"))->setText("ACME");
        dialog.findChild<QListWidget *>(QStringLiteral("reportRuns"))
            ->item(0)
            ->setCheckState(Qt::Checked);
        EXPECT_EQ(dialog.saveTo(dir.filePath(QStringLiteral("r.json"))), QString());
    }
    EXPECT_EQ(seen.lang, dev::Language::German);
    EXPECT_EQ(seen.runs, std::vector<int>{0});
    const Json json = readJson(dir.filePath(QStringLiteral("r.json")));
    EXPECT_EQ(json["header"]["customer"], "ACME");
    EXPECT_EQ(json["language"], "de");
    ui::ReportDialog again({}, dev::Language::English, maker);
    EXPECT_EQ(again.findChild<QLineEdit *>(QStringLiteral("reportCustomer"))->text(), "ACME");
}

// The Workbench's comparison with a reference fingerprint becomes the report's drift section: the
// parameter named in the report's language with its values as the editor shows them, the figures
// named as the Workbench names them, the step overlays kept and a sweep's (on a frequency axis)
// left to its figures.
TEST(ReportDrift, TheReferenceComparisonInTheReportsWords)
{
    const auto &dictionaries = dev::builtinDictionaries();
    ASSERT_TRUE(dictionaries.ok());
    const dev::Dictionary *dma = dictionaries->find("dma-pn-v51");
    ASSERT_NE(dma, nullptr);
    const dev::ParamMeta *gain = dma->find("C1.13");
    ASSERT_NE(gain, nullptr);

    model::Reference reference;
    reference.file.saved = "2026-11-20T09:30:00.000+01:00";
    reference.file.family = "dma-pn-v51";
    reference.file.address = 2;
    reference.file.setValue = "A1.01";
    model::ReferenceComparison comparison;
    model::ParamDrift param;
    param.module = 2;
    param.row = "C1.13";
    param.name = "whatever the comparison said";
    param.reference = 2.0;
    param.now = 1.0;
    param.referenceRaw = 200;
    param.nowRaw = 100;
    param.unit = gain->unit;
    comparison.params.push_back(param);
    comparison.metrics.push_back(model::metricDrift(model::DriftMetric::RiseTime, 0.10, 0.25, {}));
    comparison.metrics.back().module = 2;
    comparison.metrics.back().test = "step-up";
    comparison.overlays.push_back({"step-up", false, {0, 0.1}, {0, 1}, {0, 0.5}});
    comparison.overlays.push_back({"sweep", true, {1, 2}, {0, -3}, {0, -6}});

    const model::ReportDrift drift = model::reportDrift(
        reference, comparison, QStringLiteral("/tmp/axis.vtref"), dma, dev::Language::German);
    EXPECT_EQ(drift.referenceFile, QStringLiteral("/tmp/axis.vtref"));
    EXPECT_EQ(drift.takenAt.toUTC(), QDateTime(QDate(2026, 11, 20), QTime(8, 30), Qt::UTC));
    ASSERT_EQ(drift.params.size(), 1u);
    EXPECT_EQ(drift.params[0].module, 2);
    EXPECT_EQ(drift.params[0].name.toStdString(), gain->label.de);
    EXPECT_EQ(drift.params[0].reference, model::formatRaw(*gain, 200.0, dev::Language::German));
    EXPECT_EQ(drift.params[0].now, model::formatRaw(*gain, 100.0, dev::Language::German));
    ASSERT_EQ(drift.metrics.size(), 1u);
    EXPECT_EQ(drift.metrics[0].test, QStringLiteral("step up"));
    EXPECT_EQ(drift.metrics[0].metric, QStringLiteral("rise time 10–90 %"));
    EXPECT_DOUBLE_EQ(drift.metrics[0].deltaPercent, 150.0);
    EXPECT_TRUE(drift.metrics[0].exceeded);
    ASSERT_EQ(drift.curves.size(), 1u);
    EXPECT_EQ(drift.curves[0].module, 2);
    EXPECT_EQ(drift.curves[0].now, (std::vector<double>{0, 0.5}));
}

// The dialog offers the drift only when the Workbench has a comparison, ticked.
TEST(ReportDialogTest, OffersTheDriftOnlyWhenThereIsAComparison)
{
    const ui::ReportMaker none = [](const ui::ReportChoice &, const auto &) { return QString(); };
    ui::ReportDialog without({}, dev::Language::English, none);
    EXPECT_FALSE(without.choice().drift);
    ui::ReportDialog with({}, dev::Language::English, none);
    with.offerDrift(QStringLiteral("axis.vtref"));
    EXPECT_TRUE(with.choice().drift);
    auto *box = with.findChild<QCheckBox *>(QStringLiteral("reportDrift"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains(QStringLiteral("axis.vtref")));
    box->setChecked(false);
    EXPECT_FALSE(with.choice().drift);
}

// After the fact: the writes of another session (here a valvetune-cli set, whose session log is on
// disk) become the report's write log with --session-log; a log that cannot be read is refused.
TEST(ReportCli, TheWriteLogComesFromASessionLog)
{
    QTemporaryDir dir;
    const QString logs = dir.filePath(QStringLiteral("sessions"));
    const CliRun set =
        cli({"--audit-dir", logs, "set", "--sim", "dma-pn-v51", "--yes", "C1.07=1.250"});
    ASSERT_EQ(set.code, cli::kExitOk) << what(set);
    const QStringList files = QDir(logs).entryList({QStringLiteral("*.jsonl")}, QDir::Files);
    ASSERT_EQ(files.size(), 1) << files.join(' ').toStdString();
    const QString log = QDir(logs).filePath(files.front());

    const QString vtpar = dir.filePath(QStringLiteral("node.vtpar"));
    ASSERT_EQ(cli({"read", "--sim", "dma-pn-v51", "--out", vtpar}).code, cli::kExitOk);
    const QString out = dir.filePath(QStringLiteral("r.json"));
    const CliRun report = cli({"report", "--file", vtpar, "--session-log", log, "--out", out});
    ASSERT_EQ(report.code, cli::kExitOk) << what(report);
    const Json json = readJson(out);
    ASSERT_EQ(json["writes"].size(), 1u) << json["writes"].dump();
    EXPECT_EQ(json["writes"][0]["row"], "C1.07");
    EXPECT_EQ(json["writes"][0]["status"], "verified");
    EXPECT_EQ(json["writes"][0]["new"], "1.250 V");
    // In a German report the log's values and names are said in German.
    const CliRun german =
        cli({"report", "--file", vtpar, "--session-log", log, "--out", out, "--lang", "de"});
    ASSERT_EQ(german.code, cli::kExitOk) << what(german);
    const Json de = readJson(out);
    EXPECT_EQ(de["writes"][0]["new"], "1,250 V");
    const auto &dictionaries = dev::builtinDictionaries();
    ASSERT_TRUE(dictionaries.ok());
    EXPECT_EQ(de["writes"][0]["name"], dictionaries->find("dma-pn-v51")->find("C1.07")->label.de);

    const CliRun missing = cli({"report", "--file", vtpar, "--session-log",
                                dir.filePath(QStringLiteral("none.jsonl")), "--out", out});
    EXPECT_EQ(missing.code, cli::kExitUsage) << what(missing);
    EXPECT_TRUE(missing.complains("none.jsonl")) << missing.err;
}

TEST(ReportCli, RefusesAnUnknownFormatAndAMissingOut)
{
    const CliRun noOut = cli({"report", "--sim", "opat"});
    EXPECT_EQ(noOut.code, cli::kExitUsage) << what(noOut);
    EXPECT_TRUE(noOut.complains("--out")) << noOut.err;
    const CliRun doc = cli({"report", "--sim", "opat", "--out", "/tmp/x.doc"});
    EXPECT_EQ(doc.code, cli::kExitUsage) << what(doc);
    const CliRun missing =
        cli({"report", "--file", "/nonexistent/x.vtpar", "--out", "/tmp/x.json"});
    EXPECT_EQ(missing.code, cli::kExitUsage) << what(missing);
}

} // namespace
} // namespace vt::test
