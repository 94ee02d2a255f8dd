// What the writers hand the session log (audit_log.h): one line per finished write item, built
// from a WriteJob's item (with its read back) or from one exchange that wrote without a read back
// (a test signal's set value, the inspector's composed frame), tagged with the window or CLI
// command it came from. Every function does nothing when no AuditLog is installed.
// GUI thread only, like the AuditLog.
#pragma once

#include "model/audit/audit_record.h"
#include "model/session/session.h"
#include "model/session/write_record.h"

#include <QString>
#include <optional>
#include <vector>

namespace vt::model {

// Which window or CLI command made a write.
enum class AuditOrigin {
    Editor,    // the parameter editor's Write changes
    Monitor,   // the monitor's set-value step
    Workbench, // the tuning workbench: test signals, set value restore, guided tuning's gains
    Compose,   // the telegram inspector's composed frames
    Fold,      // the fold wizard's apply
    State,     // the device state control (mode, enable)
    Restore,   // putting back what a valve-moving write changed (actuator_restore.h)
    CliSet,
    CliWrite,
    CliTest,
};
const char *auditOriginKey(AuditOrigin origin);

// A write item as the job left it: status, read back and reason (English, and German when the
// text is the device's or the session runs in German).
void auditWrite(int module, const WriteItem &item, AuditOrigin origin);
// One exchange that wrote `value` to `row` (nullptr: a raw frame, `frameHex` its bytes) without a
// read back: written, refused, uncertain or not sent, from the outcome.
void auditExchange(int module, const dev::ParamMeta *row,
                   const std::optional<dev::RawValue> &before, const dev::RawValue &value,
                   const Outcome &outcome, AuditOrigin origin, const QString &frameHex = {});
// The connection of the session (Connection::describe()); empty: disconnected.
void auditConnection(const QString &connection);

} // namespace vt::model
