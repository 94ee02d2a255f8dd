#include "cli_app.h"

#include "commands.h"

#include <QCoreApplication>
#include <algorithm>
#include <nlohmann/json.hpp>

namespace vt::cli {
namespace {

const char kProgram[] = "valvetune-cli";

void printHelp(std::ostream &out)
{
    out << "Usage: " << kProgram << " [--json] [--audit-dir DIR] COMMAND [ARGS...]\n"
        << "       " << kProgram << " --help | --version\n\n"
        << "ValveTune on the command line: decode and build telegrams, inspect dictionaries and\n"
        << "talk to devices.\n\n"
        << "Options:\n"
        << "  --json      machine-readable output (JSON) on stdout\n"
        << "  --audit-dir DIR\n"
        << "              keep the session log of every write in DIR (default\n"
        << "              ~/.local/share/ValveTune/sessions, or $VT_AUDIT_DIR)\n"
        << "  --help      this text; COMMAND --help for a command's own options\n"
        << "  --version   program version\n\n";
    if (commands().empty()) {
        out << "No commands are available in this version yet.\n";
    } else {
        out << "Commands:\n";
        for (const Command &c : commands())
            out << "  " << c.name << std::string(c.name.size() < 12 ? 12 - c.name.size() : 1, ' ')
                << c.summary << '\n';
    }
    out << "\nWrites that can move the valve (set values, E17, control words) ask on a terminal\n"
        << "and need --yes without one.\n"
        << "\nExit codes: 0 ok, 1 device or protocol error, 2 usage error (also: a valve-moving\n"
        << "write not confirmed), 3 connection error, 4 verification failed.\n";
}

} // namespace

int Context::fail(int code, const std::string &message) const
{
    err << kProgram << ": " << message << '\n';
    return code;
}

// Timers, sockets, the serial worker and translators need a QCoreApplication. main() makes one;
// a program that calls runCli() without one (the in-process golden tests) gets one here, for good:
// Qt allows one per process and it must outlive every QObject the commands made.
void ensureApplication()
{
    if (QCoreApplication::instance())
        return;
    static int argc = 1;
    static char name[] = "valvetune-cli";
    static char *argv[] = {name, nullptr};
    new QCoreApplication(argc, argv); // NOLINT: lives until the process ends, by design
}

void Context::useLanguage(dev::Language language)
{
    ensureApplication();
    lang = language;
    const QString code =
        language == dev::Language::German ? QStringLiteral("de") : QStringLiteral("en");
    if (translation && translation->code() == code)
        return;
    translation.reset();
    translation = i18n::Translation::load(code);
    if (translation)
        translation->install();
}

const std::vector<Command> &commands()
{
    static const std::vector<Command> list = {
        {"decode", "explain a telegram field by field (any protocol)", runDecode},
        {"encode", "build gateway CMD 3/6/15 and Modbus RTU frames", runEncode},
        {"dictionary", "list device families, show a family's parameters", runDictionary},
        {"info", "identify the modules of a connection (family, version, mode, address)", runInfo},
        {"scan", "list the addresses that answer", runScan},
        {"read", "read every parameter; print it or save the settings as a .vtpar file (--out)",
         runRead},
        {"get", "read parameters by name", runGet},
        {"set", "write parameters in display units, verified; asks first if the valve can move",
         runSet},
        {"write", "write a .vtpar file's changed settings, verified (--dry-run: list them)",
         runWrite},
        {"diff", "compare a .vtpar file with the device", runDiff},
        {"monitor", "poll display values at a rate for a time (--csv)", runMonitor},
        {"test", "drive the set value with a step, sine or sweep; step figures, gain and phase",
         runTest},
        {"report", "commissioning report of a node or a .vtpar file (PDF, HTML or JSON)",
         runReport},
        {"reference", "save a module's settings and step/sweep responses; compare them later",
         runReference},
        {"fold", "plan a multi-module node's PLC configuration (GSD, byte map)", runFold},
    };
    return list;
}

int runCli(const QStringList &arguments, std::ostream &out, std::ostream &err, Console console)
{
    Context ctx{out, err, false, console};
    QStringList rest = arguments.mid(1);
    // Global options come before the command; --json is also accepted after it.
    while (!rest.isEmpty() && rest.first().startsWith(QLatin1String("--"))) {
        const QString opt = rest.takeFirst();
        if (opt == QLatin1String("--help")) {
            printHelp(out);
            return kExitOk;
        }
        if (opt == QLatin1String("--version")) {
            if (ctx.json)
                out << nlohmann::ordered_json{{"name", kProgram}, {"version", VT_VERSION}}.dump()
                    << '\n';
            else
                out << kProgram << ' ' << VT_VERSION << '\n';
            return kExitOk;
        }
        if (opt == QLatin1String("--json")) {
            ctx.json = true;
            continue;
        }
        if (opt == QLatin1String("--audit-dir")) {
            if (rest.isEmpty() || rest.first().isEmpty())
                return ctx.fail(kExitUsage, "--audit-dir needs a directory");
            ctx.auditDir = rest.takeFirst();
            continue;
        }
        return ctx.fail(kExitUsage, "unknown option '" + opt.toStdString() + "' (see --help)");
    }
    if (rest.isEmpty())
        return ctx.fail(kExitUsage, "no command given (see --help)");

    const std::string name = rest.takeFirst().toStdString();
    const auto &list = commands();
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const Command &c) { return c.name == name; });
    if (it == list.end())
        return ctx.fail(kExitUsage, "unknown command '" + name + "' (see --help)");
    if (rest.removeAll(QStringLiteral("--json")) > 0)
        ctx.json = true;
    return it->run(rest, ctx);
}

} // namespace vt::cli
