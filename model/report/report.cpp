#include "report.h"

#include "files/file_rows.h"
#include "files/param_file_map.h"
#include "model/fold/fold_node_check.h"

#include <map>

namespace vt::model {

namespace {

std::string major(const std::string &version)
{
    return version.substr(0, version.find('.'));
}

bool applies(const dev::ParamMeta &row, const std::string &version, const std::string &mode)
{
    return row.access != dev::Access::Inactive && row.access != dev::Access::NotImplemented &&
           row.appliesTo(major(version), mode);
}

std::map<const dev::ParamMeta *, dev::RawValue> valuesOf(const dev::Dictionary &dictionary,
                                                         const dev::files::ModuleRecord &record)
{
    std::map<const dev::ParamMeta *, dev::RawValue> values;
    for (const dev::files::ValueRow &v : record.values)
        if (const dev::ParamMeta *meta = dev::files::findMeta(dictionary, v))
            values.emplace(meta, v.raw);
    return values;
}

int number(const std::string &text)
{
    try {
        return text.empty() ? 0 : std::stoi(text);
    } catch (const std::exception &) {
        return 0;
    }
}

// A node of HCS modules (every module a fold module of one node type): its PLC sheet.
std::optional<FoldSheet> foldOf(const std::vector<ReportModule> &modules)
{
    if (modules.empty())
        return std::nullopt;
    std::optional<FoldNode> node;
    std::vector<FoldNodeModule> found;
    for (const ReportModule &m : modules) {
        if (!m.dictionary)
            return std::nullopt;
        const auto own = foldNodeOfFamily(m.dictionary->family);
        if (!own || (node && *own != *node))
            return std::nullopt;
        node = own;
        found.push_back({m.address, number(major(m.version)), number(m.mode)});
    }
    if (modules.size() > foldMaxCmd15Modules(*node))
        return std::nullopt;
    return makeFoldSheet(foldPlanFromNode(defaultFoldPlan(*node, found.size()), found));
}

} // namespace

bool ReportSetting::differsFromDefault() const
{
    return row && row->defaultValue && !dev::isText(value) &&
           dev::rawNumber(value) != *row->defaultValue;
}

bool ReportSetting::differsFromReference() const
{
    return reference && *reference != value;
}

std::size_t Report::settingCount() const
{
    std::size_t n = 0;
    for (const ReportModule &m : modules)
        n += m.settings.size();
    return n;
}

Report assembleReport(ReportInput input, const dev::DictionarySet &dictionaries, dev::Language lang)
{
    Report report;
    report.header = std::move(input.header);
    report.created = input.created.isValid() ? input.created : QDateTime::currentDateTime();
    report.toolVersion = QStringLiteral(VT_VERSION);
    report.connection = std::move(input.connection);
    report.sourceFile = std::move(input.sourceFile);
    report.referenceFile = std::move(input.referenceFile);
    report.writes = std::move(input.writes);
    report.runs = std::move(input.runs);
    report.drift = std::move(input.drift);
    report.lang = lang;

    for (const dev::files::ModuleRecord &record : input.settings.modules) {
        ReportModule module;
        module.address = record.address;
        module.dictionary = dictionaries.find(record.family);
        module.version = record.version;
        module.mode = record.mode;
        module.label = record.label;
        if (const auto it = input.identities.find(record.address); it != input.identities.end())
            module.identity = it->second;
        const dev::files::ModuleRecord *reference =
            input.reference ? input.reference->findModule(record.address) : nullptr;
        module.inReference = reference != nullptr;
        if (module.dictionary) {
            const auto values = valuesOf(*module.dictionary, record);
            std::map<const dev::ParamMeta *, dev::RawValue> referenceValues;
            if (reference && reference->family == record.family)
                referenceValues = valuesOf(*module.dictionary, *reference);
            for (const dev::ParamMeta &row : module.dictionary->params) {
                const auto value = values.find(&row);
                if (!dev::files::isFileRow(row) || !applies(row, record.version, record.mode) ||
                    value == values.end())
                    continue;
                ReportSetting setting{&row, value->second, std::nullopt};
                if (const auto ref = referenceValues.find(&row); ref != referenceValues.end())
                    setting.reference = ref->second;
                module.settings.push_back(std::move(setting));
            }
        }
        report.modules.push_back(std::move(module));
    }
    report.fold = foldOf(report.modules);
    return report;
}

} // namespace vt::model
