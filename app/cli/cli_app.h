// valvetune-cli's front: global options (--help, --version, --json), subcommand dispatch and the
// output conventions: --json puts machine-readable output on stdout, human errors are one line
// on stderr, exit codes from exit_codes.h. Streams are parameters so golden tests can run it
// in-process.
#pragma once

#include "exit_codes.h"

#include <QStringList>
#include <functional>
#include <istream>
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

struct Context
{
    std::ostream &out;
    std::ostream &err;
    bool json = false;
    Console console;

    // Prints "valvetune-cli: <message>" on stderr and returns the code.
    int fail(int code, const std::string &message) const;
};

struct Command
{
    std::string name;
    std::string summary;
    // args: the subcommand's own arguments (without the program and subcommand name).
    std::function<int(const QStringList &args, Context &ctx)> run;
};

// Registered subcommands, in --help order.
const std::vector<Command> &commands();

// arguments include the program name.
int runCli(const QStringList &arguments, std::ostream &out, std::ostream &err,
           Console console = {});

} // namespace vt::cli
