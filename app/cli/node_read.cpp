#include "node_read.h"

#include "files/file_rows.h"

#include <algorithm>
#include <chrono>

namespace vt::cli {

namespace {

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

} // namespace

std::optional<std::vector<ModuleRead>> readNode(DeviceRun &run, int *code)
{
    const auto identified = run.identifyModules(code);
    if (!identified)
        return std::nullopt;

    std::vector<ModuleRead> reads;
    for (const model::IdentifyResult &r : *identified) {
        // A file that misses a module of the node is no backup of it: a module that does not
        // identify ends the command before anything is saved.
        auto module = run.accept(r, code);
        if (!module)
            return std::nullopt;
        const int address = module->address;
        auto result = run.read(address, model::readableRows(*module->dictionary,
                                                            module->identification.version,
                                                            module->identification.mode));
        if (!result) {
            *code = run.failDeadline("module " + std::to_string(address) + ": read");
            return std::nullopt;
        }
        reportFailures(run.ctx(), address, *result, run.lang());
        printWarnings(run.ctx().err, address, result->values, run.lang());
        for (const model::RowFailure &f : result->failures) {
            // Rows this protocol cannot carry (the field device status over HART) are reported,
            // not an error.
            if (f.outcome.status != model::OutcomeStatus::NotEncodable || f.outcome.sent)
                *code =
                    std::max(*code, run.linkLost() ? int(kExitConnection) : exitCodeOf(f.outcome));
        }
        reads.push_back({*module, *result});
        if (run.linkLost())
            break;
    }
    return reads;
}

dev::files::ParamFile paramFileOf(const std::vector<ModuleRead> &reads)
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
    return file;
}

} // namespace vt::cli
