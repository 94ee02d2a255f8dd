#include "file_plan.h"

#include "files/param_file.h"
#include "files/param_file_map.h"

#include <QFile>
#include <algorithm>

namespace vt::cli {

namespace {

const char *statusKey(dev::files::MapStatus status)
{
    switch (status) {
    case dev::files::MapStatus::Mapped: return "mapped";
    case dev::files::MapStatus::MappedByAddress: return "mapped-by-address";
    case dev::files::MapStatus::Unknown: return "unknown";
    case dev::files::MapStatus::OutOfRange: return "out-of-range";
    case dev::files::MapStatus::NotApplicable: return "not-applicable";
    case dev::files::MapStatus::TypeMismatch: return "type-mismatch";
    case dev::files::MapStatus::Missing: return "missing";
    }
    return "?";
}

std::optional<dev::files::ParamFile> load(Context &ctx, const QString &path, int *code)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *code = ctx.fail(kExitUsage, "cannot open " + str(path) + ": " + str(f.errorString()));
        return std::nullopt;
    }
    const QByteArray bytes = f.read(static_cast<qint64>(dev::files::kMaxFileBytes) + 1);
    auto parsed = dev::files::parseParamFile(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (!parsed.ok()) {
        *code = ctx.fail(kExitUsage, str(path) + ": " + parsed.error().text().in(ctx.lang));
        return std::nullopt;
    }
    return *parsed;
}

struct Pairing
{
    std::vector<std::pair<const dev::files::ModuleRecord *, model::ModuleInfo>> pairs;
    std::vector<UnmatchedModule> unmatched;
};

// Which record of the file goes onto which module.
std::optional<Pairing> pair(DeviceRun &run, const char *command, const dev::files::ParamFile &file,
                            const QString &path, int *code)
{
    const auto identified = run.identifyModules(code);
    if (!identified)
        return std::nullopt;
    std::vector<model::ModuleInfo> modules;
    for (const model::IdentifyResult &r : *identified) {
        auto module = run.accept(r, code);
        if (!module)
            return std::nullopt;
        modules.push_back(*module);
    }
    const auto recordAt = [&](int address) -> const dev::files::ModuleRecord * {
        for (const dev::files::ModuleRecord &record : file.modules)
            if (record.address == address)
                return &record;
        return nullptr;
    };
    Pairing pairing;
    if (!run.wholeNode() && modules.size() == 1) {
        const model::ModuleInfo &module = modules.front();
        if (file.modules.size() == 1) {
            pairing.pairs.emplace_back(&file.modules.front(), module);
            return pairing;
        }
        if (const dev::files::ModuleRecord *record = recordAt(module.address)) {
            if (!run.options().module) {
                for (const dev::files::ModuleRecord &other : file.modules)
                    if (other.address != module.address) {
                        *code =
                            failUsage(run.ctx(), command,
                                      str(path) + ": its module " + std::to_string(other.address) +
                                          " is not on this connection (use --module)");
                        return std::nullopt;
                    }
            }
            pairing.pairs.emplace_back(record, module);
            return pairing;
        }
        *code = failUsage(run.ctx(), command,
                          str(path) + " holds no module " + std::to_string(module.address));
        return std::nullopt;
    }
    for (const model::ModuleInfo &module : modules) {
        if (const dev::files::ModuleRecord *record = recordAt(module.address))
            pairing.pairs.emplace_back(record, module);
        else
            pairing.unmatched.push_back({module.address, false, {}, module});
    }
    for (const dev::files::ModuleRecord &record : file.modules) {
        const bool onNode = std::any_of(modules.begin(), modules.end(),
                                        [&](const auto &m) { return m.address == record.address; });
        if (!onNode)
            pairing.unmatched.push_back({record.address, true, record.family, {}});
    }
    return pairing;
}

} // namespace

std::optional<FilePlan> planFile(DeviceRun &run, const char *command, const QString &path,
                                 bool forWrite, int *code)
{
    Context &ctx = run.ctx();
    const auto file = load(ctx, path, code);
    if (!file)
        return std::nullopt;
    const auto pairing = pair(run, command, *file, path, code);
    if (!pairing)
        return std::nullopt;

    FilePlan filePlan;
    filePlan.unmatched = pairing->unmatched;
    std::vector<ModulePlan> &plans = filePlan.modules;
    for (const auto &[record, info] : pairing->pairs) {
        const model::ModuleInfo *module = &info;
        const int address = module->address;
        if (record->family != module->identification.family) {
            *code = ctx.fail(kExitUsage, str(path) + " is for " + record->family + "; " +
                                             moduleText(*module) +
                                             " (a file of another family is never applied)");
            return std::nullopt;
        }
        const auto report = dev::files::mapModule(
            *record, *module->dictionary,
            dev::files::MapTarget{module->identification.version, module->identification.mode});
        for (const dev::LocalText &note : report.notes)
            ctx.err << "valvetune-cli: warning: module " << address << ": " << note.in(run.lang())
                    << '\n';
        ModulePlan plan;
        plan.module = *module;
        std::vector<std::string> refused;
        for (const dev::files::RowMapping &m : report.rows) {
            if (m.status == dev::files::MapStatus::Missing)
                continue;
            if (m.ignoredForWriting) { // a process or live value: named in a note above
                plan.skipped.push_back({m.name, "not-a-setting", key(m.meta->kind)});
                continue;
            }
            const bool settable = m.meta && m.meta->writable();
            if (m.applies()) {
                if (settable)
                    plan.rows.push_back({m.meta, record->values[m.row].raw});
                continue;
            }
            const bool bad = m.status == dev::files::MapStatus::OutOfRange ||
                             m.status == dev::files::MapStatus::TypeMismatch;
            if (bad && !settable)
                continue; // a read-only row (a live value) is never written: no check
            if (bad && forWrite)
                refused.push_back(m.reason.in(run.lang()));
            plan.skipped.push_back({m.name, statusKey(m.status), m.reason.in(run.lang())});
            ctx.err << "valvetune-cli: warning: module " << address << ": " << m.name
                    << " not applied (" << m.reason.in(run.lang()) << ")\n";
        }
        if (!refused.empty()) {
            *code =
                ctx.fail(kExitUsage, str(path) + ": module " + std::to_string(address) + ": " +
                                         std::to_string(refused.size()) +
                                         " value(s) cannot be written, first: " + refused.front() +
                                         "; nothing was sent");
            return std::nullopt;
        }
        plans.push_back(std::move(plan));
    }
    return filePlan;
}

std::string unmatchedText(const std::vector<UnmatchedModule> &unmatched)
{
    std::string text;
    for (const UnmatchedModule &u : unmatched) {
        text += text.empty() ? "" : "; ";
        if (u.inFile)
            text += "the file's module " + std::to_string(u.address) + " (" + u.family +
                    ") is not on the node";
        else
            text += "the node's module " + std::to_string(u.address) + " (" +
                    u.module.identification.family + ") is not in the file";
    }
    return text;
}

Json unmatchedJson(const std::vector<UnmatchedModule> &unmatched)
{
    Json list = Json::array();
    for (const UnmatchedModule &u : unmatched)
        list.push_back(Json{{"address", u.address},
                            {"family", u.inFile ? u.family : u.module.identification.family},
                            {"in", u.inFile ? "file" : "node"}});
    return list;
}

std::optional<std::map<const dev::ParamMeta *, dev::RawValue>>
readCurrent(DeviceRun &run, const ModulePlan &plan, int *code)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const PlannedRow &r : plan.rows) {
        if (r.row->readable())
            rows.push_back(r.row);
    }
    const int address = plan.module.address;
    const auto result = run.read(address, rows);
    if (!result || run.linkLost()) {
        *code =
            run.failDeadline("module " + std::to_string(address) + ": reading the current values");
        return std::nullopt;
    }
    if (!result->failures.empty()) {
        const model::RowFailure &f = result->failures.front();
        *code = run.failExchange(address, "reading " + f.rows.front()->name, f.outcome);
        return std::nullopt;
    }
    std::map<const dev::ParamMeta *, dev::RawValue> current;
    for (const model::RowValue &v : result->values)
        current[v.row] = v.value;
    return current;
}

Json skippedJson(const std::vector<SkippedRow> &skipped)
{
    Json list = Json::array();
    for (const SkippedRow &s : skipped)
        list.push_back(Json{{"name", s.name}, {"status", s.status}, {"reason", s.reason}});
    return list;
}

} // namespace vt::cli
