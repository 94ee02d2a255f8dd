// valvetune-cli's front: global options (--help, --version, --json), subcommand dispatch and the
// output conventions: --json puts machine-readable output on stdout, human errors are one line
// on stderr, exit codes from exit_codes.h. Streams are parameters so golden tests can run it
// in-process.
#pragma once

#include "app/cmdline/arg_parse.h"
#include "app/i18n/translation.h"
#include "core/local_text.h"
#include "exit_codes.h"

#include <QStringList>
#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace vt::cli {

// Where valvetune-cli can ask the person a question (confirm_gate.h): stdin, when it is a
// terminal. The default has nobody to ask, as for a script, a pipe or a test.
struct Console
{
    bool terminal = false;
    std::istream *in = nullptr; // the answers, line by line
};
// The subcommands read their own options with the helpers valvetune's command line shares.
using cmdline::parseInteger;
using cmdline::takeFlag;
using cmdline::takeOption;

struct Context
{
    std::ostream &out;
    std::ostream &err;
    bool json = false;
    Console console;
    // --lang: the catalogue in force while the command runs, removed when runCli returns, so an
    // in-process run leaves the language as it found it.
    std::unique_ptr<i18n::Translation> translation{};
    // The same language for the texts devices/ carries in both (device refusals, file errors).
    dev::Language lang = dev::Language::English;
    // --audit-dir: where a device command's session log goes (empty: AuditLog's default).
    QString auditDir{};

    // Prints "valvetune-cli: <message>" on stderr and returns the code.
    int fail(int code, const std::string &message) const;
    // Texts worded through tr() (the session's, the links', the model's) come out in `lang`.
    void useLanguage(dev::Language language);
};

struct Command
{
    std::string name;
    std::string summary;
    // args: the subcommand's own arguments (without the program and subcommand name).
    std::function<int(const QStringList &args, Context &ctx)> run;
};

// Makes the process's QCoreApplication when there is none yet (runCli() called in-process).
void ensureApplication();

// Registered subcommands, in --help order.
const std::vector<Command> &commands();

// arguments include the program name.
int runCli(const QStringList &arguments, std::ostream &out, std::ostream &err,
           Console console = {});

} // namespace vt::cli
