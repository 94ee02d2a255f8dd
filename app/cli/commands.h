// The valvetune-cli subcommands; each lives in its own cmd_<name>.cpp.
#pragma once

#include "cli_app.h"

namespace vt::cli {

int runDictionary(const QStringList &args, Context &ctx);
int runDecode(const QStringList &args, Context &ctx);
int runEncode(const QStringList &args, Context &ctx);

} // namespace vt::cli
