// valvetune-cli's front: global options (--help, --version, --json), subcommand dispatch and the
// output conventions: --json puts machine-readable output on stdout, human errors are one line
// on stderr, exit codes from exit_codes.h. Streams are parameters so golden tests can run it
// in-process.
#pragma once

#include "app/cmdline/arg_parse.h"
#include "exit_codes.h"

#include <QStringList>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace vt::cli {

// The subcommands read their own options with the helpers valvetune's command line shares.
using cmdline::parseInteger;
using cmdline::takeFlag;
using cmdline::takeOption;

struct Context
{
    std::ostream &out;
    std::ostream &err;
    bool json = false;

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
int runCli(const QStringList &arguments, std::ostream &out, std::ostream &err);

} // namespace vt::cli
