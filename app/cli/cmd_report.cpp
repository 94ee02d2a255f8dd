// valvetune-cli report: the commissioning report (docs/REPORT.md) of a whole node read now, or of
// a parameter file offline, as PDF, HTML or JSON by the --out file's suffix:
//   report CONNECTION --out FILE [--reference FILE.vtpar] [--run RUNFILE]...
//          [--session-log FILE.jsonl] [header options]
//   report --file FILE.vtpar --out FILE [--reference …] [--run …]... [--session-log …] [header …]
// The write log comes from a session log (model/audit) named by --session-log: the writes of
// another valvetune or valvetune-cli session, also one that crashed or lost its link.
// The header options (--customer, --machine, --axis, --operator, --comment) fill the report's
// header. Rows that could not be read are listed and make the exit code 1; the report still
// holds what was read. Needs a QGuiApplication (fonts, plots): main() makes one for this command.
#include "commands.h"
#include "device_run.h"
#include "dict/dictionary_loader.h"
#include "model/params/param_file_io.h"
#include "model/report/report_render.h"
#include "model/report/report_writes.h"
#include "node_read.h"

#include <QGuiApplication>
#include <QLocale>

namespace vt::cli {

namespace {

const char kName[] = "report";
const char kSynopsis[] =
    "report (CONNECTION | --file FILE.vtpar) --out FILE.pdf|.html|.json\n"
    "       [--reference FILE.vtpar] [--run RUNFILE]... [--session-log FILE.jsonl]\n"
    "       [--customer TEXT] [--machine TEXT] [--axis TEXT] [--operator TEXT] [--comment TEXT]\n"
    "       [--lang en|de]";

struct ReportOptions
{
    QString out;
    std::optional<QString> reference;
    QStringList runs;
    std::optional<QString> sessionLog; // the write log: a session log of valvetune(-cli)
    model::ReportHeader header;
};

// The report's own options; nullopt after a usage error (*code = 2).
std::optional<ReportOptions> takeReportOptions(QStringList &args, Context &ctx, int *code)
{
    bool missing = false;
    ReportOptions o;
    const auto out = takeOption(args, QStringLiteral("--out"), &missing);
    o.reference = takeOption(args, QStringLiteral("--reference"), &missing);
    while (const auto run = takeOption(args, QStringLiteral("--run"), &missing))
        o.runs << *run;
    o.sessionLog = takeOption(args, QStringLiteral("--session-log"), &missing);
    const auto text = [&](const char *name) {
        return takeOption(args, QLatin1String(name), &missing).value_or(QString());
    };
    o.header = {text("--customer"), text("--machine"), text("--axis"), text("--operator"),
                text("--comment")};
    if (missing) {
        *code = failUsage(ctx, kName, "an option is missing its value");
        return std::nullopt;
    }
    if (!out) {
        *code = failUsage(ctx, kName, "--out FILE.pdf|.html|.json is required");
        return std::nullopt;
    }
    if (!model::reportFormatOf(*out)) {
        *code = failUsage(ctx, kName, "--out must name a .pdf, .html or .json file");
        return std::nullopt;
    }
    o.out = *out;
    return o;
}

// The reference file, the runs and the session log named on the command line, into `input`; false
// after printing why one could not be read (*code = 2).
bool loadExtras(const ReportOptions &o, const dev::DictionarySet &dictionaries, dev::Language lang,
                model::ReportInput &input, model::AuditLogContents &sessionLog, Context &ctx,
                int *code)
{
    if (o.reference) {
        auto reference = model::readParamFile(*o.reference, lang);
        if (!reference.ok()) {
            *code = ctx.fail(kExitUsage, str(reference.error()));
            return false;
        }
        input.reference = std::move(*reference);
        input.referenceFile = *o.reference;
    }
    for (const QString &path : o.runs) {
        QString why;
        auto run = model::loadRun(path, dictionaries, &why);
        if (!run) {
            *code = ctx.fail(kExitUsage, str(path) + ": " + str(why));
            return false;
        }
        input.runs.push_back(std::move(*run));
    }
    if (o.sessionLog) {
        sessionLog = model::readAuditLog(*o.sessionLog);
        const model::AuditLogContents &log = sessionLog;
        if (!log.ok) {
            *code = ctx.fail(kExitUsage, str(*o.sessionLog) + ": " + str(log.error));
            return false;
        }
        if (log.truncatedTail || log.skipped > 0)
            ctx.err << "valvetune-cli: " << str(*o.sessionLog) << ": " << log.skipped
                    << " unreadable line(s)"
                    << (log.truncatedTail ? ", the last line cut (the program was stopped "
                                            "while writing it)"
                                          : "")
                    << "; the report holds the " << log.entries.size() << " writes read\n";
    }
    return true;
}

// The number format of the report's language for texts made with QLocale() (a run's title) while
// the report is written; the process's default again afterwards.
class ReportLocale
{
public:
    explicit ReportLocale(dev::Language lang)
    {
        QLocale::setDefault(
            QLocale(lang == dev::Language::German ? QLocale::German : QLocale::English));
    }
    ~ReportLocale() { QLocale::setDefault(m_before); }
    ReportLocale(const ReportLocale &) = delete;
    ReportLocale &operator=(const ReportLocale &) = delete;

private:
    QLocale m_before;
};

int finish(Context &ctx, const ReportOptions &o, const model::Report &report, int code)
{
    const ReportLocale locale(report.lang);
    if (const auto error = model::writeReport(report, o.out))
        return ctx.fail(kExitUsage, str(*error));
    if (ctx.json)
        ctx.out << Json{{"file", str(o.out)},
                        {"modules", report.modules.size()},
                        {"settings", report.settingCount()},
                        {"runs", report.runs.size()}}
                       .dump(2)
                << '\n';
    else
        ctx.out << "wrote the report of " << report.settingCount() << " settings of "
                << report.modules.size() << " module(s) to " << str(o.out) << '\n';
    return code;
}

int reportFile(const QString &path, QStringList &args, Context &ctx)
{
    bool missing = false;
    const auto lang = takeOption(args, QStringLiteral("--lang"), &missing);
    if (missing || (lang && *lang != QLatin1String("en") && *lang != QLatin1String("de")))
        return failUsage(ctx, kName, "--lang takes en or de");
    ctx.useLanguage(lang == QLatin1String("de") ? dev::Language::German : dev::Language::English);
    int code = kExitOk;
    const auto options = takeReportOptions(args, ctx, &code);
    if (!options || !checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    const auto &dictionaries = dev::builtinDictionaries();
    if (!dictionaries.ok())
        return ctx.fail(kExitUsage, "the built-in dictionaries do not load");
    auto file = model::readParamFile(path, ctx.lang);
    if (!file.ok())
        return ctx.fail(kExitUsage, str(file.error()));
    model::ReportInput input;
    input.header = options->header;
    input.settings = std::move(*file);
    input.sourceFile = path;
    model::AuditLogContents sessionLog;
    if (!loadExtras(*options, *dictionaries, ctx.lang, input, sessionLog, ctx, &code))
        return code;
    input.writes = model::reportWrites(sessionLog, input.settings, *dictionaries, ctx.lang);
    return finish(ctx, *options, model::assembleReport(std::move(input), *dictionaries, ctx.lang),
                  kExitOk);
}

} // namespace

int runReport(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return ctx.fail(kExitUsage, "report needs a QGuiApplication (main() makes one)");
    bool missing = false;
    if (const auto file = takeOption(args, QStringLiteral("--file"), &missing)) {
        if (takeFlag(args, QStringLiteral("--help"))) {
            ctx.out << deviceUsage(kSynopsis) << '\n';
            return kExitOk;
        }
        return reportFile(*file, args, ctx);
    }
    if (missing)
        return failUsage(ctx, kName, "--file needs a parameter file");
    int code = kExitOk;
    auto device = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!device)
        return code;
    const auto options = takeReportOptions(args, ctx, &code);
    if (!options || !checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    DeviceRun run(ctx, *device);
    model::ReportInput input;
    input.header = options->header;
    model::AuditLogContents sessionLog;
    if (!loadExtras(*options, run.dictionaries(), run.lang(), input, sessionLog, ctx, &code))
        return code;
    if (const int c = run.connect())
        return c;
    const auto node = readNode(run, &code);
    if (!node)
        return code;
    std::vector<int> addresses;
    for (const ModuleRead &r : *node) {
        addresses.push_back(r.module.address);
        if (r.module.identityText.complete() || !r.module.identityText.en.empty())
            input.identities[r.module.address] = r.module.identityText;
    }
    input.settings = paramFileOf(*node);
    input.writes = model::reportWrites(sessionLog, input.settings, run.dictionaries(), run.lang());
    input.connection = QString::fromStdString(run.describe(addresses));
    return finish(ctx, *options,
                  model::assembleReport(std::move(input), run.dictionaries(), run.lang()), code);
}

} // namespace vt::cli
