// valvetune-cli set CONNECTION NAME=VALUE... [--yes] [--module ADDRESS] [--lang en|de] [--json]:
// write parameters of one module (default: the first) in display units ("C1.07=1.000", German
// "C1.07=1,000", an enum label, text for text rows). Every value is parsed and range-checked
// against the dictionary before anything is sent: a value out of range, for a read-only or an
// unknown parameter exits 2 and nothing reaches the device. A change that can move the actuator
// (a set value, E17, a control word) passes the confirmation gate (confirm_gate.h). Then a safe
// write (WriteJob): only changed values, paced, each read back — exit 4 when a read back differs,
// 1 when the device refuses, 3 when the link is lost.
#include "commands.h"
#include "confirm_gate.h"
#include "device_run.h"
#include "dict/cooking.h"

namespace vt::cli {

namespace {

const char kName[] = "set";
const char kSynopsis[] =
    "set CONNECTION NAME=VALUE... [--yes] [--module ADDRESS] [--lang en|de] [--json]\n"
    "  --yes  write set values, E17 and control words without asking (needed without a terminal)";

} // namespace

int runSet(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    ConfirmGate gate(ctx, args);
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options || !checkPositional(args, ctx, kName, 1, 4096, &code))
        return code;
    for (const QString &a : args) {
        if (a.indexOf(QLatin1Char('=')) <= 0)
            return failUsage(ctx, kName, "expected NAME=VALUE, got '" + str(a) + "'");
    }
    DeviceRun run(ctx, *options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    const int address = module->address;

    // Everything is checked before anything is sent.
    std::vector<model::WriteItem> items;
    for (const QString &a : args) {
        const std::string name = str(a.section(QLatin1Char('='), 0, 0).trimmed());
        const std::string text = str(a.section(QLatin1Char('='), 1));
        const dev::ParamMeta *row = findRow(*module, name);
        if (!row)
            return failUsage(ctx, kName,
                             "unknown parameter '" + name + "' for " +
                                 module->identification.family);
        if (!row->writable())
            return ctx.fail(kExitUsage, row->name + " cannot be written (" +
                                            dev::accessText(row->access).in(run.lang()) +
                                            "); nothing was sent");
        model::WriteItem item;
        item.row = row;
        if (row->isString()) {
            if (row->length > 0 && text.size() > static_cast<std::size_t>(row->length))
                return ctx.fail(kExitUsage, row->name + ": text longer than " +
                                                std::to_string(row->length) +
                                                " bytes; nothing was sent");
            item.value = text;
        } else {
            const auto parsed = dev::parseValue(*row, text, run.lang());
            if (!parsed.ok())
                return ctx.fail(kExitUsage,
                                parsed.error().message.in(run.lang()) + "; nothing was sent");
            if (const auto error = dev::checkWrite(*row, *parsed))
                return ctx.fail(kExitUsage, error->message.in(run.lang()) + "; nothing was sent");
            item.value = *parsed;
        }
        if (!appliesToModule(*row, *module))
            ctx.err << "valvetune-cli: warning: " << row->name << " is not listed for "
                    << moduleText(*module) << "; sending it, the module decides\n";
        items.push_back(std::move(item));
    }

    // What the device holds now: unchanged values are not written again.
    std::vector<const dev::ParamMeta *> readable;
    for (const model::WriteItem &item : items) {
        if (item.row->readable())
            readable.push_back(item.row);
    }
    const auto before = run.read(address, readable);
    if (!before || run.linkLost())
        return run.failDeadline("module " + std::to_string(address) +
                                ": reading the current values");
    for (model::WriteItem &item : items) {
        for (const model::RowValue &v : before->values) {
            if (v.row == item.row)
                item.before = v.value;
        }
    }

    if (const int c = gate.pass(run, *module, items))
        return c;
    const std::vector<model::WriteItem> done =
        run.write(*module, std::move(items), model::AuditOrigin::CliSet);
    code = exitCodeOf(done, run.linkLost());
    if (ctx.json) {
        Json results = Json::array();
        bool complete = true;
        for (const model::WriteItem &item : done) {
            results.push_back(writeItemJson(item, run.lang()));
            complete = complete && model::isOnDevice(item.status);
        }
        ctx.out << Json{{"module", moduleJson(*module)},
                        {"results", results},
                        {"complete", complete}}
                       .dump(2)
                << '\n';
    } else {
        for (const model::WriteItem &item : done)
            printWriteItem(ctx.out, item, run.lang());
    }
    if (code != kExitOk)
        ctx.err << "valvetune-cli: the write did not complete (see the status of each parameter)\n";
    return code;
}

} // namespace vt::cli
