// valvetune-cli read CONNECTION [--module ADDRESS] [--out FILE] [--lang en|de] [--json]: read every
// readable row of every module of the node (DeviceRun::identifyModules()) or of the one --module
// names; print name and value, or save a .vtpar parameter file (docs/FILE-FORMAT.md) of the
// settings (files/file_rows.h: no process or live values). Rows that
// could not be read are listed and make the exit code 1; a file still holds what was read.
#include "commands.h"
#include "device_run.h"
#include "files/file_rows.h"
#include "files/param_file.h"

#include <QSaveFile>
#include <algorithm>
#include <chrono>

namespace vt::cli {

namespace {

const char kName[] = "read";
const char kSynopsis[] = "read CONNECTION [--module ADDRESS] [--out FILE] [--lang en|de] [--json]";

struct ModuleRead
{
    model::ModuleInfo module;
    model::ReadResult result;
};

Json failuresJson(const model::ReadResult &result, dev::Language lang)
{
    Json list = Json::array();
    for (const model::RowFailure &f : result.failures) {
        Json names = Json::array();
        for (const dev::ParamMeta *row : f.rows)
            names.push_back(row->name);
        list.push_back(Json{{"names", names}, {"error", outcomeText(f.outcome, lang)}});
    }
    return list;
}

// One line per distinct reason (a lost link fails every exchange still queued alike).
void reportFailures(Context &ctx, int address, const model::ReadResult &result, dev::Language lang)
{
    std::vector<std::pair<std::string, std::vector<std::string>>> byReason;
    for (const model::RowFailure &f : result.failures) {
        const std::string reason = outcomeText(f.outcome, lang);
        auto it = std::find_if(byReason.begin(), byReason.end(),
                               [&](const auto &r) { return r.first == reason; });
        if (it == byReason.end())
            it = byReason.insert(byReason.end(), {reason, {}});
        for (const dev::ParamMeta *row : f.rows)
            it->second.push_back(row->name);
    }
    for (const auto &[reason, names] : byReason)
        ctx.err << "valvetune-cli: module " << address << ": " << names.size()
                << " row(s) not read (" << names.front() << (names.size() > 1 ? " …" : "")
                << "): " << reason << '\n';
}

std::optional<std::string> save(const QString &path, const std::vector<ModuleRead> &reads,
                                const dev::DictionarySet &dictionaries, dev::Language lang)
{
    dev::files::ParamFile file;
    file.tool = std::string("ValveTune ") + VT_VERSION;
    file.created = dev::files::isoUtc(std::chrono::system_clock::now());
    for (const ModuleRead &r : reads) {
        dev::files::ModuleRecord record;
        record.address = r.module.address;
        record.family = r.module.identification.family;
        record.version = r.module.identification.version;
        record.mode = r.module.identification.mode;
        for (const model::RowValue &v : r.result.values)
            if (dev::files::isFileRow(*v.row))
                record.values.push_back(dev::files::makeValueRow(*v.row, v.value));
        file.modules.push_back(std::move(record));
    }
    const std::string text = dev::files::writeParamFile(file, &dictionaries, lang);
    QSaveFile out(path); // atomic: a failed save never leaves half a file
    if (!out.open(QIODevice::WriteOnly))
        return "cannot write " + str(path) + ": " + str(out.errorString());
    out.write(text.data(), static_cast<qint64>(text.size()));
    if (!out.commit())
        return "cannot write " + str(path) + ": " + str(out.errorString());
    return std::nullopt;
}

std::vector<int> addressesOf(const std::vector<ModuleRead> &reads)
{
    std::vector<int> addresses;
    for (const ModuleRead &r : reads)
        addresses.push_back(r.module.address);
    return addresses;
}

} // namespace

int runRead(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    bool missing = false;
    const auto outPath = takeOption(args, QStringLiteral("--out"), &missing);
    if (missing)
        return failUsage(ctx, kName, "--out needs a file name");
    if (!checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    DeviceRun run(ctx, *options);
    if (const int c = run.connect())
        return c;
    const auto identified = run.identifyModules(&code);
    if (!identified)
        return code;

    std::vector<ModuleRead> reads;
    for (const model::IdentifyResult &r : *identified) {
        // A file that misses a module of the node is no backup of it: a module that does not
        // identify ends the command before anything is saved.
        auto module = run.accept(r, &code);
        if (!module)
            return code;
        const int address = module->address;
        auto result = run.read(address, model::readableRows(*module->dictionary,
                                                            module->identification.version,
                                                            module->identification.mode));
        if (!result)
            return run.failDeadline("module " + std::to_string(address) + ": read");
        reportFailures(ctx, address, *result, run.lang());
        printWarnings(ctx.err, address, result->values, run.lang());
        for (const model::RowFailure &f : result->failures) {
            // Rows this protocol cannot carry (the field device status over HART) are reported,
            // not an error.
            if (f.outcome.status != model::OutcomeStatus::NotEncodable || f.outcome.sent)
                code =
                    std::max(code, run.linkLost() ? int(kExitConnection) : exitCodeOf(f.outcome));
        }
        reads.push_back({*module, *result});
        if (run.linkLost())
            break;
    }

    if (outPath) {
        if (const auto error = save(*outPath, reads, run.dictionaries(), run.lang()))
            return ctx.fail(kExitUsage, *error);
    }
    if (ctx.json) {
        Json modules = Json::array();
        for (const ModuleRead &r : reads) {
            Json m = moduleJson(r.module);
            m["count"] = r.result.values.size();
            if (!outPath) {
                Json values = Json::array();
                for (const model::RowValue &v : r.result.values)
                    values.push_back(valueJson(*v.row, v.value, run.lang()));
                m["values"] = values;
            }
            m["failures"] = failuresJson(r.result, run.lang());
            modules.push_back(m);
        }
        Json doc{{"connection", run.describe(addressesOf(reads))}};
        doc["file"] = outPath ? Json(str(*outPath)) : Json(nullptr);
        doc["modules"] = modules;
        ctx.out << doc.dump(2) << '\n';
    } else if (outPath) {
        std::size_t values = 0;
        for (const ModuleRead &r : reads)
            values += static_cast<std::size_t>(std::count_if(
                r.result.values.begin(), r.result.values.end(),
                [](const model::RowValue &v) { return dev::files::isFileRow(*v.row); }));
        ctx.out << "wrote " << values << " settings of " << reads.size() << " module(s) to "
                << str(*outPath) << '\n';
    } else {
        for (const ModuleRead &r : reads) {
            ctx.out << moduleText(r.module) << '\n';
            for (const model::RowValue &v : r.result.values)
                printValue(ctx.out, *v.row, v.value, run.lang(), "  ");
        }
    }
    return code;
}

} // namespace vt::cli
