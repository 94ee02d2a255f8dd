#include "model/audit/write_audit.h"

#include "dict/cooking.h"
#include "model/audit/audit_log.h"
#include "model/text_language.h"

namespace vt::model {

namespace {

struct OriginKey
{
    AuditOrigin origin;
    const char *key;
};
constexpr OriginKey kOriginKeys[] = {
    {AuditOrigin::Editor, "editor"},       {AuditOrigin::Monitor, "monitor"},
    {AuditOrigin::Workbench, "workbench"}, {AuditOrigin::Compose, "compose"},
    {AuditOrigin::Fold, "fold"},           {AuditOrigin::State, "state"},
    {AuditOrigin::Restore, "restore"},     {AuditOrigin::CliSet, "cli-set"},
    {AuditOrigin::CliWrite, "cli-write"},  {AuditOrigin::CliTest, "cli-test"},
};

std::string rawText(const dev::RawValue &value)
{
    if (dev::isText(value))
        return std::get<std::string>(value);
    return QString::number(dev::rawNumber(value), 'g', 17).toStdString();
}

AuditValue auditValue(const dev::ParamMeta *row, const std::optional<dev::RawValue> &value)
{
    if (!value)
        return {};
    if (dev::isText(*value) || !row)
        return {rawText(*value), rawText(*value)};
    return {dev::formatValue(*row, dev::rawNumber(*value), dev::Language::English),
            rawText(*value)};
}

AuditWriteRecord record(int module, const dev::ParamMeta *row,
                        const std::optional<dev::RawValue> &before, const dev::RawValue &value,
                        AuditOrigin origin)
{
    AuditWriteRecord r;
    r.time = AuditLog::now();
    r.module = module;
    if (row) {
        r.row = row->name;
        r.name = row->label.en;
        r.unit = row->unit;
    }
    r.oldValue = auditValue(row, before);
    r.newValue = auditValue(row, value);
    r.origin = auditOriginKey(origin);
    return r;
}

// The application's words in English, and in German when that is the language in force.
void setReason(AuditWriteRecord &r, const dev::LocalText &deviceText, const Sentence &reason)
{
    if (!deviceText.en.empty()) {
        r.reasonEn = deviceText.en;
        r.reasonDe = deviceText.de;
        return;
    }
    r.reasonEn = reason.english().toStdString();
    if (textLanguage() == dev::Language::German)
        r.reasonDe = reason.text().toStdString();
}

} // namespace

const char *auditOriginKey(AuditOrigin origin)
{
    for (const OriginKey &k : kOriginKeys)
        if (k.origin == origin)
            return k.key;
    return "?";
}

void auditWrite(int module, const WriteItem &item, AuditOrigin origin)
{
    AuditLog *log = AuditLog::current();
    // An unchanged row was not written (a file's write lists every setting of the module).
    if (!log || item.status == WriteStatus::Unchanged)
        return;
    AuditWriteRecord r = record(module, item.row, item.before, item.value, origin);
    r.status = writeStatusKey(item.status);
    r.readBack = auditValue(item.row, item.readBack);
    setReason(r, item.deviceText, item.reason);
    log->append(r);
}

void auditExchange(int module, const dev::ParamMeta *row,
                   const std::optional<dev::RawValue> &before, const dev::RawValue &value,
                   const Outcome &outcome, AuditOrigin origin, const QString &frameHex)
{
    AuditLog *log = AuditLog::current();
    if (!log)
        return;
    AuditWriteRecord r = record(module, row, before, value, origin);
    if (!row && !frameHex.isEmpty())
        r.newValue = {frameHex.toStdString(), frameHex.toStdString()};
    WriteStatus status = WriteStatus::Written;
    switch (outcome.status) {
    case OutcomeStatus::Ok: break;
    case OutcomeStatus::DeviceException: status = WriteStatus::Refused; break;
    case OutcomeStatus::NotEncodable: status = WriteStatus::RefusedLocally; break;
    case OutcomeStatus::Timeout:
    case OutcomeStatus::LinkLost:
    case OutcomeStatus::Cancelled:
        status = outcome.sent ? WriteStatus::Uncertain : WriteStatus::NotSent;
        break;
    }
    r.status = writeStatusKey(status);
    setReason(r, outcome.reply.exceptionText, Sentence::verbatim(outcome.reason));
    log->append(r);
}

void auditConnection(const QString &connection)
{
    if (AuditLog *log = AuditLog::current())
        log->setConnection(connection);
}

} // namespace vt::model
