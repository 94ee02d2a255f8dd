// DeviceRun: the life of one valvetune-cli device command — the connection built from the shared
// options, an event loop of its own for every step (so a command works from main() before
// QCoreApplication::exec() and from the in-process golden tests alike), bounded by a deadline,
// identification of the modules, and the exit code of whatever failed (exit_codes.h).
// Owner: the command's run function, on the thread that called runCli().
#pragma once

#include "cli_app.h"
#include "connection_args.h"
#include "device_output.h"
#include "model/audit/audit_log.h"
#include "model/session/connection.h"
#include "model/session/write_record.h"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QEventLoop;

namespace vt::cli {

class DeviceRun
{
public:
    // Each wait of a command ends after this at the latest (monitor: its duration on top).
    static constexpr std::chrono::milliseconds kStepLimit{120'000};

    DeviceRun(Context &ctx, DeviceOptions options);
    ~DeviceRun();
    DeviceRun(const DeviceRun &) = delete;
    DeviceRun &operator=(const DeviceRun &) = delete;

    // Builds and opens the connection: kExitOk, or the exit code after printing why.
    int connect();

    Context &ctx() const { return m_ctx; }
    const DeviceOptions &options() const { return m_options; }
    dev::Language lang() const { return m_options.lang; }
    model::Connection &connection() const { return *m_connection; }
    model::DeviceAccess &access() const { return m_connection->access(); }
    const dev::DictionarySet &dictionaries() const;

    // The addresses a command works on: --module, else every module (all) or the first one.
    // nullopt after printing a usage error (--module names no module of a simulator).
    std::optional<std::vector<int>> select(bool all);

    // A node link: TCP (a Modbus TCP gateway or the node image) without --unit. Its modules are
    // the addresses that answer a scan, found as the GUI's Device ▸ Scan finds them.
    bool nodeLink() const;
    // The command covers every module of a node (a node link or a simulated node), not one
    // module: no --module and no --unit.
    bool wholeNode() const;
    // The modules info, read, diff and write work on, identified, in address order: --module's;
    // on a node link every address that answers a scan (Connection::scanAddresses()); else every
    // module of the connection. Results that failed are included (not ok) except addresses that
    // only told that no module is there. nullopt after printing why (*exitCode: 2 usage, 3 the
    // link was lost, 1 no module answered).
    std::optional<std::vector<model::IdentifyResult>> identifyModules(int *exitCode);
    // The module of an identification, its warning printed; nullopt after printing why it
    // failed (*exitCode says how to exit).
    std::optional<model::ModuleInfo> accept(const model::IdentifyResult &result, int *exitCode);
    // The connection with the modules a command worked on: on a node link "tcp 127.0.0.1:502,
    // modbus-tcp, modules 1, 2, 3" (Connection::describe() names the default unit there, not the
    // modules found or --module's); elsewhere Connection::describe().
    std::string describe(const std::vector<int> &addresses) const;

    // Identifies one module (bounded). nullopt after printing why; *exitCode says how to exit.
    std::optional<model::ModuleInfo> identify(int address, int *exitCode);
    // Connects, then identifies the module a single-module command (get, set, monitor) works
    // on: --module or the first. nullopt after printing why; *exitCode says how to exit.
    std::optional<model::ModuleInfo> connectFirstModule(int *exitCode);
    // Identifies several at once; the results in the order of `addresses` (failures included).
    std::vector<model::IdentifyResult> identifyEach(const std::vector<int> &addresses);
    // Reads `rows` of `address` (bounded); nullopt when the deadline passed.
    std::optional<model::ReadResult> read(int address, std::vector<const dev::ParamMeta *> rows);

    // Runs a safe write (model::WriteJob: range check, changed only, paced, read back) to its end,
    // bounded; the items as the job left them (rows not reached stay NotSent).
    // The session log names `origin` (the command) for each item.
    std::vector<model::WriteItem> write(const model::ModuleInfo &module,
                                        std::vector<model::WriteItem> items,
                                        model::AuditOrigin origin);

    // Runs the event loop until `done()` holds or `limit` passed (false), or — with stopOnLost —
    // the link is lost (false). Callbacks that change what `done` looks at call wake().
    bool waitUntil(const std::function<bool()> &done, std::chrono::milliseconds limit = kStepLimit,
                   bool stopOnLost = false);
    void wake();

    bool linkLost() const { return m_lost; }
    const QString &lostReason() const { return m_lostReason; }
    // Prints "module N: <what>: <reason>" and returns the exit code of a failed exchange.
    int failExchange(int address, const std::string &what, const model::Outcome &outcome);
    // Prints the deadline message and returns the exit code (1).
    int failDeadline(const std::string &what);

private:
    Context &m_ctx;
    DeviceOptions m_options;
    // The session log of this command's writes; outlives the connection, whose close it logs.
    model::AuditLog m_audit;
    model::AuditLog::Scope m_auditScope{m_audit};
    std::unique_ptr<model::Connection> m_connection;
    QEventLoop *m_loop = nullptr; // the innermost waitUntil's loop
    bool m_lost = false;
    QString m_lostReason;
};

// Common usage: the command's synopsis followed by the connection options.
std::string deviceUsage(const char *synopsis);

// The start of every device command: --help (prints the usage, *code = 0) and the shared
// options (a usage error prints one line, *code = 2). nullopt when the command is over.
std::optional<DeviceOptions> startCommand(QStringList &args, Context &ctx, const char *name,
                                          const char *synopsis, int *code);
// After the command took its own options: what is left must be `min`..`max` positional
// arguments and no option. false after printing a usage error (*code = 2).
bool checkPositional(const QStringList &args, Context &ctx, const char *name, qsizetype min,
                     qsizetype max, int *code);
// A usage error of command `name`: one line on stderr, exit 2.
int failUsage(Context &ctx, const char *name, const std::string &message);

// The row exists in the module's software version and mode (as readableRows() decides).
bool appliesToModule(const dev::ParamMeta &row, const model::ModuleInfo &module);

// The dictionary row `name` of the module, or nullptr.
const dev::ParamMeta *findRow(const model::ModuleInfo &module, const std::string &name);
// The rows `names` of the module, each readable. nullopt after printing a usage error of command
// `command` (unknown or unreadable name; *code = 2).
std::optional<std::vector<const dev::ParamMeta *>>
readableRowsNamed(const QStringList &names, const model::ModuleInfo &module, Context &ctx,
                  const char *command, int *code);

} // namespace vt::cli
