// valvetune-cli diff CONNECTION FILE [--module ADDRESS] [--lang en|de] [--json]: compare a .vtpar
// file with the device, row by row. Compared are the settable parameters (read/write rows) —
// what `write FILE` would change; live display values and the version are not. On a whole node
// each module of the file is compared with the node's module at its address, and a module on one
// side only is listed. Exit 0 whether or not values differ (the output says); 2 for a file that
// does not fit (another family, or a module on one side only), 1/3 when reading fails.
#include "commands.h"
#include "file_plan.h"

namespace vt::cli {

namespace {

const char kName[] = "diff";
const char kSynopsis[] = "diff CONNECTION FILE [--module ADDRESS] [--lang en|de] [--json]";

} // namespace

int runDiff(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options || !checkPositional(args, ctx, kName, 1, 1, &code))
        return code;
    DeviceRun run(ctx, *options);
    if (const int c = run.connect())
        return c;
    const auto plans = planFile(run, kName, args.front(), false, &code);
    if (!plans)
        return code;

    Json modules = Json::array();
    bool equal = true;
    for (const ModulePlan &plan : plans->modules) {
        const auto current = readCurrent(run, plan, &code);
        if (!current)
            return code;
        Json differences = Json::array();
        std::size_t compared = 0;
        std::vector<const PlannedRow *> differing;
        for (const PlannedRow &r : plan.rows) {
            const auto it = current->find(r.row);
            if (it == current->end())
                continue; // write-only: cannot be compared
            ++compared;
            if (sameValue(*r.row, r.value, it->second))
                continue;
            differing.push_back(&r);
            Json file = valueJson(*r.row, r.value, run.lang());
            Json device = valueJson(*r.row, it->second, run.lang());
            differences.push_back(
                Json{{"name", r.row->name},
                     {"file", Json{{"raw", file["raw"]}, {"display", file["display"]}}},
                     {"device", Json{{"raw", device["raw"]}, {"display", device["display"]}}}});
        }
        equal = equal && differing.empty();
        if (ctx.json) {
            Json m = moduleJson(plan.module);
            m["compared"] = compared;
            m["differences"] = differences;
            m["skipped"] = skippedJson(plan.skipped);
            modules.push_back(m);
            continue;
        }
        ctx.out << moduleText(plan.module) << ": ";
        if (differing.empty())
            ctx.out << "no differences (" << compared << " parameters compared)\n";
        else
            ctx.out << differing.size() << (differing.size() == 1 ? " difference" : " differences")
                    << " (" << compared << " parameters compared)\n";
        for (const PlannedRow *r : differing)
            ctx.out << "  " << r->row->name << "  file " << displayOf(*r->row, r->value, run.lang())
                    << ", device " << displayOf(*r->row, current->at(r->row), run.lang()) << '\n';
    }
    const std::vector<UnmatchedModule> &unmatched = plans->unmatched;
    if (ctx.json) {
        ctx.out << Json{{"file", str(args.front())},
                        {"equal", equal && unmatched.empty()},
                        {"modules", modules},
                        {"unmatched", unmatchedJson(unmatched)}}
                       .dump(2)
                << '\n';
    } else {
        for (const UnmatchedModule &u : unmatched) {
            if (u.inFile)
                ctx.out << "module " << u.address << ": in the file (" << u.family
                        << "), not on the node\n";
            else
                ctx.out << moduleText(u.module) << ": on the node, not in the file\n";
        }
    }
    if (!unmatched.empty())
        return ctx.fail(kExitUsage,
                        str(args.front()) + " does not fit the node: " + unmatchedText(unmatched));
    return kExitOk;
}

} // namespace vt::cli
