// valvetune-cli get CONNECTION NAME... [--module ADDRESS] [--lang en|de] [--json]: read named
// parameters of one module (default: the first) and print them in display units.
#include "commands.h"
#include "device_run.h"

namespace vt::cli {

namespace {

const char kName[] = "get";
const char kSynopsis[] = "get CONNECTION NAME... [--module ADDRESS] [--lang en|de] [--json]";

} // namespace

int runGet(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options || !checkPositional(args, ctx, kName, 1, 4096, &code))
        return code;
    DeviceRun run(ctx, *options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    const int address = module->address;

    auto named = readableRowsNamed(args, *module, ctx, kName, &code);
    if (!named)
        return code;
    std::vector<const dev::ParamMeta *> rows = std::move(*named);
    const auto result = run.read(address, rows);
    if (!result)
        return run.failDeadline("module " + std::to_string(address) + ": get");
    if (!result->failures.empty())
        return run.failExchange(address, "reading " + result->failures.front().rows.front()->name,
                                result->failures.front().outcome);
    printWarnings(ctx.err, address, result->values, run.lang());
    if (ctx.json) {
        Json values = Json::array();
        for (const model::RowValue &v : result->values)
            values.push_back(valueJson(*v.row, v.value, run.lang()));
        ctx.out << Json{{"module", moduleJson(*module)}, {"values", values}}.dump(2) << '\n';
    } else {
        for (const model::RowValue &v : result->values)
            printValue(ctx.out, *v.row, v.value, run.lang());
    }
    return kExitOk;
}

} // namespace vt::cli
