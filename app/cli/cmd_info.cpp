// valvetune-cli info CONNECTION [--module ADDRESS] [--json]: identify the modules (family,
// software version, mode, address) and show the device's own texts (HART tag, long tag,
// descriptor, date, message): every module of a node (DeviceRun::identifyModules()), or the one
// --module or --unit names. A warning the device sent with a value is printed as a warning.
#include "commands.h"
#include "device_run.h"
#include "model/session/identity_texts.h"

namespace vt::cli {

namespace {

const char kName[] = "info";
const char kSynopsis[] = "info CONNECTION [--module ADDRESS] [--json]";

} // namespace

int runInfo(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options || !checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    DeviceRun run(ctx, *options);
    if (const int c = run.connect())
        return c;
    const auto results = run.identifyModules(&code);
    if (!results)
        return code;
    std::vector<int> addresses;
    for (const model::IdentifyResult &r : *results)
        addresses.push_back(r.module.address);
    const std::string connection = run.describe(addresses);
    Json modules = Json::array();
    if (!ctx.json)
        ctx.out << "connection: " << connection << '\n';
    for (const model::IdentifyResult &r : *results) {
        if (!r.ok) {
            const std::string why = r.failure.status != model::OutcomeStatus::Ok
                                        ? outcomeText(r.failure, run.lang())
                                        : str(model::identifyMessage(r, run.lang()));
            code =
                std::max(code, r.failure.status == model::OutcomeStatus::LinkLost || run.linkLost()
                                   ? int(kExitConnection)
                                   : int(kExitDeviceError));
            ctx.err << "valvetune-cli: module " << r.module.address << ": " << why << '\n';
            modules.push_back(Json{{"address", r.module.address}, {"ok", false}, {"error", why}});
            continue;
        }
        Json m{{"address", r.module.address}, {"ok", true}};
        m.update(moduleJson(r.module));
        m["title"] =
            r.module.dictionary ? r.module.dictionary->title.in(run.lang()) : std::string();
        if (!ctx.json)
            ctx.out << moduleText(r.module) << " — " << m["title"].get<std::string>() << '\n';
        if (r.module.dictionary) {
            const auto rows = model::identityTextRows(*r.module.dictionary);
            const auto read = rows.empty() ? std::nullopt : run.read(r.module.address, rows);
            if (read) {
                Json texts = Json::object();
                const auto lines = model::identityTexts(
                    *r.module.dictionary,
                    [&read](const dev::ParamMeta *row) -> std::optional<dev::RawValue> {
                        for (const model::RowValue &v : read->values)
                            if (v.row == row)
                                return v.value;
                        return std::nullopt;
                    },
                    run.lang());
                for (const model::IdentityText &t : lines) {
                    texts[t.key] = str(t.value);
                    if (!ctx.json)
                        ctx.out << "  " << str(t.label) << ": " << str(t.value) << '\n';
                }
                m["texts"] = texts;
                // HART-7 manual §4.4.1 "Status": a warning comes with the value; both are said.
                printWarnings(ctx.err, r.module.address, read->values, run.lang());
                for (const model::RowFailure &f : read->failures)
                    ctx.err << "valvetune-cli: warning: module " << r.module.address << ": "
                            << outcomeText(f.outcome, run.lang()) << '\n';
            }
        }
        modules.push_back(m);
        if (!model::identifyMessage(r, run.lang()).isEmpty())
            ctx.err << "valvetune-cli: warning: module " << r.module.address << ": "
                    << str(model::identifyMessage(r, run.lang())) << '\n';
    }
    if (ctx.json)
        ctx.out << Json{{"connection", connection}, {"modules", modules}}.dump(2) << '\n';
    return code;
}

} // namespace vt::cli
