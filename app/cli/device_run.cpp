#include "device_run.h"

#include "dict/dictionary_loader.h"
#include "model/session/write_job.h"
#include "sim_memory.h"
#include "transports/fault_link.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>
#include <algorithm>

namespace vt::cli {

namespace {

constexpr std::chrono::milliseconds kOpenLimit{30'000};

std::string joined(const std::vector<int> &addresses)
{
    std::string s;
    for (int a : addresses)
        s += (s.empty() ? "" : ", ") + std::to_string(a);
    return s;
}

} // namespace

std::string deviceUsage(const char *synopsis)
{
    return std::string("usage: valvetune-cli ") + synopsis + "\n" + deviceSynopsis();
}

std::optional<DeviceOptions> startCommand(QStringList &args, Context &ctx, const char *name,
                                          const char *synopsis, int *code)
{
    if (takeFlag(args, QStringLiteral("--help"))) {
        ctx.out << deviceUsage(synopsis) << '\n';
        *code = kExitOk;
        return std::nullopt;
    }
    auto options = takeDeviceOptions(args);
    if (!options.ok()) {
        *code = failUsage(ctx, name, options.error());
        return std::nullopt;
    }
    ctx.useLanguage(options->lang);
    return *options;
}

bool checkPositional(const QStringList &args, Context &ctx, const char *name, qsizetype min,
                     qsizetype max, int *code)
{
    if (const auto option = leftoverOption(args)) {
        *code = failUsage(ctx, name, "unknown option '" + str(*option) + "'");
        return false;
    }
    if (args.size() < min || args.size() > max) {
        *code = failUsage(ctx, name,
                          args.size() < min ? "missing arguments"
                                            : "unexpected argument '" + str(args.last()) + "'");
        return false;
    }
    return true;
}

int failUsage(Context &ctx, const char *name, const std::string &message)
{
    return ctx.fail(kExitUsage, message + " (see valvetune-cli " + name + " --help)");
}

bool appliesToModule(const dev::ParamMeta &row, const model::ModuleInfo &module)
{
    const std::string &version = module.identification.version;
    std::string major;
    for (char c : version) {
        if (c < '0' || c > '9')
            break;
        major.push_back(c);
    }
    return row.appliesTo(major, module.identification.mode);
}

const dev::ParamMeta *findRow(const model::ModuleInfo &module, const std::string &name)
{
    return module.dictionary ? module.dictionary->find(name) : nullptr;
}

std::optional<std::vector<const dev::ParamMeta *>>
readableRowsNamed(const QStringList &names, const model::ModuleInfo &module, Context &ctx,
                  const char *command, int *code)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const QString &name : names) {
        const dev::ParamMeta *row = findRow(module, str(name));
        if (!row) {
            *code = failUsage(ctx, command,
                              "unknown parameter '" + str(name) + "' for " +
                                  module.identification.family);
            return std::nullopt;
        }
        if (!row->readable()) {
            *code = failUsage(ctx, command,
                              row->name + " cannot be read (" +
                                  dev::accessText(row->access).in(ctx.lang) + ")");
            return std::nullopt;
        }
        rows.push_back(row);
    }
    return rows;
}

DeviceRun::DeviceRun(Context &ctx, DeviceOptions options)
    : m_ctx(ctx), m_options(std::move(options)),
      m_audit(QStringLiteral("valvetune-cli"), QStringLiteral(VT_VERSION), ctx.auditDir)
{
    ensureApplication();
    // Errors are one line on stderr (cli_app.h): the links' log lines (vt.link …) would repeat
    // them. QT_LOGGING_RULES brings them back for debugging.
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        QLoggingCategory::setFilterRules(QStringLiteral("vt.*=false"));
}

DeviceRun::~DeviceRun()
{
    if (!m_connection)
        return;
    if (model::SimEndpoint *sim = m_connection->simEndpoint())
        rememberSimulator(*sim);
    m_connection->close();
    m_connection.reset();
}

const dev::DictionarySet &DeviceRun::dictionaries() const
{
    return *dev::builtinDictionaries();
}

int DeviceRun::connect()
{
    if (!dev::builtinDictionaries().ok())
        return m_ctx.fail(kExitDeviceError, "the built-in dictionaries do not load");
    auto made = model::Connection::create(m_options.spec, dictionaries());
    if (!made.ok())
        return m_ctx.fail(kExitUsage, str(made.error()));
    m_connection = std::move(made).value();
    if (model::SimEndpoint *sim = m_connection->simEndpoint())
        restoreSimulator(*sim);

    bool opened = false;
    std::optional<QString> failure;
    QObject guard; // disconnects the lambdas below when this function returns
    QObject::connect(m_connection.get(), &model::Connection::opened, &guard, [&] {
        opened = true;
        wake();
    });
    QObject::connect(m_connection.get(), &model::Connection::failed, &guard,
                     [&](const QString &reason) {
                         failure = reason;
                         wake();
                     });
    QObject::connect(m_connection.get(), &model::Connection::lost, m_connection.get(),
                     [this](const QString &reason) {
                         m_lost = true;
                         m_lostReason = reason;
                         wake();
                     });
    m_connection->open();
    if (!waitUntil([&] { return opened || failure.has_value(); }, kOpenLimit))
        return m_ctx.fail(kExitConnection,
                          "cannot open " + str(m_connection->describe()) + ": no answer in time");
    if (failure)
        return m_ctx.fail(kExitConnection,
                          "cannot open " + str(m_connection->describe()) + ": " + str(*failure));
    return kExitOk;
}

std::optional<std::vector<int>> DeviceRun::select(bool all)
{
    const std::vector<int> addresses = m_connection->moduleAddresses();
    if (m_options.module) {
        const int m = *m_options.module;
        if (m_connection->simEndpoint() &&
            std::find(addresses.begin(), addresses.end(), m) == addresses.end()) {
            m_ctx.fail(kExitUsage, "--module " + std::to_string(m) +
                                       " is not on this connection (modules " + joined(addresses) +
                                       ")");
            return std::nullopt;
        }
        return std::vector<int>{m};
    }
    if (all || addresses.empty())
        return addresses;
    return std::vector<int>{addresses.front()};
}

std::vector<model::IdentifyResult> DeviceRun::identifyEach(const std::vector<int> &addresses)
{
    auto results =
        std::make_shared<std::vector<std::optional<model::IdentifyResult>>>(addresses.size());
    auto remaining = std::make_shared<std::size_t>(addresses.size());
    for (std::size_t i = 0; i < addresses.size(); ++i) {
        access().identify(addresses[i],
                          [this, results, remaining, i](const model::IdentifyResult &r) {
                              (*results)[i] = r;
                              --*remaining;
                              wake();
                          });
    }
    waitUntil([remaining] { return *remaining == 0; });
    std::vector<model::IdentifyResult> out;
    for (std::size_t i = 0; i < addresses.size(); ++i) {
        if ((*results)[i]) {
            out.push_back(*(*results)[i]);
        } else {
            model::IdentifyResult late;
            late.module.address = addresses[i];
            late.failure.status = model::OutcomeStatus::Timeout;
            late.failure.reason = QStringLiteral("no result before the command's deadline");
            late.message = late.failure.reason;
            out.push_back(late);
        }
    }
    return out;
}

bool DeviceRun::nodeLink() const
{
    return m_options.spec.kind == model::ConnectionKind::Tcp && !m_options.spec.unit;
}

bool DeviceRun::wholeNode() const
{
    return !m_options.module && (nodeLink() || m_connection->moduleAddresses().size() > 1);
}

std::optional<std::vector<model::IdentifyResult>> DeviceRun::identifyModules(int *exitCode)
{
    if (!nodeLink() || m_options.module) {
        const auto addresses = select(true);
        if (!addresses) {
            *exitCode = kExitUsage;
            return std::nullopt;
        }
        return identifyEach(*addresses);
    }
    const std::vector<int> tried = m_connection->scanAddresses();
    const std::vector<model::IdentifyResult> results = identifyEach(tried);
    if (m_lost) {
        *exitCode = m_ctx.fail(kExitConnection, "the link was lost while looking for the node's "
                                                "modules: " +
                                                    str(m_lostReason));
        return std::nullopt;
    }
    std::vector<model::IdentifyResult> found;
    for (const model::IdentifyResult &r : results) {
        // A gateway answers for an address without a module with an exception ("timeout
        // (Modbus)"), others stay silent: neither is a module. Something that answers but is not
        // identified is one, and is reported.
        if (r.ok || r.failure.status == model::OutcomeStatus::Ok)
            found.push_back(r);
    }
    if (found.empty()) {
        *exitCode =
            m_ctx.fail(kExitDeviceError, "no module answered on " + describe({}) + " (addresses " +
                                             std::to_string(tried.front()) + ".." +
                                             std::to_string(tried.back()) + " tried)");
        return std::nullopt;
    }
    return found;
}

std::string DeviceRun::describe(const std::vector<int> &addresses) const
{
    if (!nodeLink())
        return str(m_connection->describe());
    const link::Link &wire =
        m_connection->faultLink() ? m_connection->faultLink()->inner() : m_connection->link();
    std::string text = str(wire.description()) + ", " + str(m_connection->protocolKey());
    if (!addresses.empty())
        text += (addresses.size() == 1 ? ", module " : ", modules ") + joined(addresses);
    if (m_options.spec.fault)
        text += " [fault " + str(m_options.spec.fault->toString()) + "]";
    return text;
}

std::optional<model::ModuleInfo> DeviceRun::identify(int address, int *exitCode)
{
    return accept(identifyEach({address}).front(), exitCode);
}

std::optional<model::ModuleInfo> DeviceRun::accept(const model::IdentifyResult &r, int *exitCode)
{
    const int address = r.module.address;
    if (r.ok) {
        if (!model::identifyMessage(r, lang()).isEmpty())
            m_ctx.err << "valvetune-cli: warning: module " << address << ": "
                      << str(model::identifyMessage(r, lang())) << '\n';
        return r.module;
    }
    if (r.failure.status != model::OutcomeStatus::Ok)
        *exitCode = failExchange(address, "identify", r.failure);
    else
        *exitCode = m_ctx.fail(kExitDeviceError, "module " + std::to_string(address) + ": " +
                                                     str(model::identifyMessage(r, lang())));
    return std::nullopt;
}

std::optional<model::ModuleInfo> DeviceRun::connectFirstModule(int *exitCode)
{
    if (const int c = connect()) {
        *exitCode = c;
        return std::nullopt;
    }
    const auto addresses = select(false);
    if (!addresses || addresses->empty()) {
        *exitCode = kExitUsage;
        return std::nullopt;
    }
    return identify(addresses->front(), exitCode);
}

std::optional<model::ReadResult> DeviceRun::read(int address,
                                                 std::vector<const dev::ParamMeta *> rows)
{
    auto result = std::make_shared<std::optional<model::ReadResult>>();
    access().read(address, std::move(rows), model::Priority::User,
                  [this, result](const model::ReadResult &r) {
                      *result = r;
                      wake();
                  });
    if (!waitUntil([result] { return result->has_value(); }))
        return std::nullopt;
    return **result;
}

std::vector<model::WriteItem> DeviceRun::write(const model::ModuleInfo &module,
                                               std::vector<model::WriteItem> items,
                                               model::AuditOrigin origin)
{
    auto job = std::make_unique<model::WriteJob>(access(), module.address, *module.dictionary,
                                                 std::move(items), origin);
    auto finished = std::make_shared<bool>(false);
    QObject::connect(job.get(), &model::WriteJob::finished, job.get(), [this, finished] {
        *finished = true;
        wake();
    });
    job->start();
    if (waitUntil([finished] { return *finished; }))
        return job->items();
    // The deadline passed: stop after the exchange on the wire. The job's callbacks may still
    // come, so it lives on with the connection (whose session goes first).
    job->cancel();
    std::vector<model::WriteItem> record = job->items();
    job.release()->setParent(m_connection.get());
    return record;
}

bool DeviceRun::waitUntil(const std::function<bool()> &done, std::chrono::milliseconds limit,
                          bool stopOnLost)
{
    QEventLoop loop;
    QEventLoop *outer = m_loop;
    m_loop = &loop;
    bool expired = false;
    QTimer deadline;
    deadline.setSingleShot(true);
    QObject::connect(&deadline, &QTimer::timeout, &loop, [&] {
        expired = true;
        loop.quit();
    });
    deadline.start(limit);
    while (!done() && !expired && !(stopOnLost && m_lost))
        loop.exec();
    m_loop = outer;
    return done();
}

void DeviceRun::wake()
{
    if (m_loop)
        m_loop->quit();
}

int DeviceRun::failExchange(int address, const std::string &what, const model::Outcome &outcome)
{
    const int code = m_lost ? kExitConnection : exitCodeOf(outcome);
    std::string reason = outcomeText(outcome, lang());
    if (m_lost && outcome.status != model::OutcomeStatus::LinkLost)
        reason = str(m_lostReason);
    return m_ctx.fail(code,
                      "module " + std::to_string(address) + ": " + what + " failed: " + reason);
}

int DeviceRun::failDeadline(const std::string &what)
{
    if (m_lost)
        return m_ctx.fail(kExitConnection, what + ": the link was lost: " + str(m_lostReason));
    return m_ctx.fail(kExitDeviceError, what + ": no result within " +
                                            std::to_string(kStepLimit.count() / 1000) + " s");
}

} // namespace vt::cli
