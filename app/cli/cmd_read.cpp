// valvetune-cli read CONNECTION [--module ADDRESS] [--out FILE] [--lang en|de] [--json]: read every
// readable row of every module of the node (DeviceRun::identifyModules()) or of the one --module
// names; print name and value, or save a .vtpar parameter file (docs/FILE-FORMAT.md) of the
// settings (files/file_rows.h: no process or live values). Rows that
// could not be read are listed and make the exit code 1; a file still holds what was read.
#include "commands.h"
#include "device_run.h"
#include "files/file_rows.h"
#include "files/param_file.h"
#include "node_read.h"

#include <QSaveFile>
#include <algorithm>

namespace vt::cli {

namespace {

const char kName[] = "read";
const char kSynopsis[] = "read CONNECTION [--module ADDRESS] [--out FILE] [--lang en|de] [--json]";

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

std::optional<std::string> save(const QString &path, const std::vector<ModuleRead> &reads,
                                const dev::DictionarySet &dictionaries, dev::Language lang)
{
    const std::string text = dev::files::writeParamFile(paramFileOf(reads), &dictionaries, lang);
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
    const auto node = readNode(run, &code);
    if (!node)
        return code;
    const std::vector<ModuleRead> &reads = *node;

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
