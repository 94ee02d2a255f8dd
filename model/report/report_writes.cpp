#include "model/report/report_writes.h"

#include "model/params/parameter_tree_model.h"

#include <optional>

namespace vt::model {

namespace {

const dev::ParamMeta *rowOf(const AuditEntry &entry, const dev::files::ParamFile &settings,
                            const dev::DictionarySet &dictionaries)
{
    for (const dev::files::ModuleRecord &m : settings.modules)
        if (m.address == entry.module)
            if (const dev::Dictionary *dictionary = dictionaries.find(m.family))
                return dictionary->find(entry.row.toStdString());
    return nullptr;
}

// A logged raw value as the row holds it; nullopt when the log has none (an unknown old value)
// or it is no number where the row wants one.
std::optional<dev::RawValue> rawOf(const dev::ParamMeta &row, const QString &raw)
{
    if (raw.isEmpty())
        return std::nullopt;
    if (row.isString())
        return dev::RawValue(raw.toStdString());
    bool ok = false;
    const double number = raw.toDouble(&ok);
    return ok ? std::optional<dev::RawValue>(number) : std::nullopt;
}

QString valueText(const dev::ParamMeta *row, const QString &raw, const QString &logged,
                  dev::Language lang)
{
    if (!row)
        return logged;
    const auto value = rawOf(*row, raw);
    return value ? formatRaw(*row, *value, lang) : logged;
}

} // namespace

std::vector<ReportWrite> reportWrites(const AuditLogContents &log,
                                      const dev::files::ParamFile &settings,
                                      const dev::DictionarySet &dictionaries, dev::Language lang)
{
    std::vector<ReportWrite> writes;
    writes.reserve(log.entries.size());
    for (const AuditEntry &e : log.entries) {
        const dev::ParamMeta *row = rowOf(e, settings, dictionaries);
        const std::string label = row ? row->label.in(lang) : std::string();
        writes.push_back(
            {e.time, e.module, e.row, label.empty() ? e.name : QString::fromStdString(label),
             e.unit, valueText(row, e.oldRaw, e.oldText, lang),
             valueText(row, e.newRaw, e.newText, lang), e.status,
             QString::fromStdString(e.reason.en), QString::fromStdString(e.reason.de)});
    }
    return writes;
}

} // namespace vt::model
