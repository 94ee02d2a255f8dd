// valvetune-cli write CONNECTION FILE [--dry-run] [--yes] [--module ADDRESS] [--lang en|de]
// [--json]: put a .vtpar file's settings on the device — only the ones that differ, each
// range-checked before sending, paced and read back (WriteJob); process and live values in the
// file are listed and never written. A file of another family, or with a value out of range, is
// refused whole (exit 2, nothing sent); a change that can move the actuator (E17, internal set
// values) passes the confirmation gate first (confirm_gate.h). --dry-run reads the device and
// lists what would change. On a whole node every module of the file goes to its own module; a
// file that lacks a module of the node, or holds one the node lacks, is refused whole (exit 2,
// nothing sent) — --module writes one. Exit 4 when a read back differs, 1 when the device
// refuses, 3 when the link is lost.
#include "commands.h"
#include "confirm_gate.h"
#include "file_plan.h"

namespace vt::cli {

namespace {

const char kName[] = "write";
const char kSynopsis[] =
    "write CONNECTION FILE [--dry-run] [--yes] [--module ADDRESS] [--lang en|de] [--json]\n"
    "  --yes  write E17, internal set values and enables without asking (needed without a "
    "terminal)";

} // namespace

int runWrite(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    const bool dryRun = takeFlag(args, QStringLiteral("--dry-run"));
    ConfirmGate gate(ctx, args);
    if (!checkPositional(args, ctx, kName, 1, 1, &code))
        return code;
    DeviceRun run(ctx, *options);
    if (const int c = run.connect())
        return c;
    const auto plans = planFile(run, kName, args.front(), true, &code);
    if (!plans)
        return code;
    if (!plans->unmatched.empty())
        return ctx.fail(kExitUsage, str(args.front()) + " does not fit the node: " +
                                        unmatchedText(plans->unmatched) +
                                        "; nothing was sent (--module ADDRESS writes one module)");
    if (!dryRun) {
        std::vector<GateItem> gated;
        for (const ModulePlan &plan : plans->modules)
            for (const PlannedRow &r : plan.rows)
                gated.push_back({&plan.module, r.row, r.value, std::nullopt});
        if (const int c = gate.pass(run, std::move(gated)))
            return c;
    }

    Json modules = Json::array();
    bool complete = true;
    for (const ModulePlan &plan : plans->modules) {
        const auto current = readCurrent(run, plan, &code);
        if (!current)
            return code;
        std::vector<model::WriteItem> items;
        for (const PlannedRow &r : plan.rows) {
            model::WriteItem item;
            item.row = r.row;
            item.value = r.value;
            if (const auto it = current->find(r.row); it != current->end())
                item.before = it->second;
            items.push_back(std::move(item));
        }
        std::size_t unchanged = 0;
        if (dryRun) {
            std::vector<model::WriteItem> changes;
            for (const model::WriteItem &item : items) {
                if (item.before && sameValue(*item.row, item.value, *item.before))
                    ++unchanged;
                else
                    changes.push_back(item);
            }
            items = std::move(changes);
        } else {
            items = run.write(plan.module, std::move(items), model::AuditOrigin::CliWrite);
            code = std::max(code, exitCodeOf(items, run.linkLost()));
            std::vector<model::WriteItem> reported;
            for (const model::WriteItem &item : items) {
                if (item.status == model::WriteStatus::Unchanged)
                    ++unchanged;
                else
                    reported.push_back(item);
                complete = complete && model::isOnDevice(item.status);
            }
            items = std::move(reported);
        }
        if (ctx.json) {
            Json changes = Json::array();
            for (const model::WriteItem &item : items)
                changes.push_back(writeItemJson(item, run.lang()));
            Json m = moduleJson(plan.module);
            m["changes"] = changes;
            m["unchanged"] = unchanged;
            m["skipped"] = skippedJson(plan.skipped);
            modules.push_back(m);
            continue;
        }
        ctx.out << moduleText(plan.module) << ": " << items.size()
                << (dryRun ? " would change" : (items.size() == 1 ? " change" : " changes")) << ", "
                << unchanged << " unchanged\n";
        for (const model::WriteItem &item : items) {
            ctx.out << "  ";
            printWriteItem(ctx.out, item, run.lang());
        }
        if (run.linkLost())
            break;
    }
    if (ctx.json)
        ctx.out << Json{{"file", str(args.front())},
                        {"dry_run", dryRun},
                        {"complete", dryRun ? Json(nullptr) : Json(complete)},
                        {"modules", modules}}
                       .dump(2)
                << '\n';
    if (code != kExitOk)
        ctx.err << "valvetune-cli: the write did not complete (see the status of each parameter)\n";
    return code;
}

} // namespace vt::cli
