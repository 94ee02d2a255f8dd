// The valvetune-cli subcommands; each lives in its own cmd_<name>.cpp.
#pragma once

#include "cli_app.h"

namespace vt::cli {

int runDictionary(const QStringList &args, Context &ctx);
int runDecode(const QStringList &args, Context &ctx);
int runEncode(const QStringList &args, Context &ctx);

// Device commands (connection options: connection_args.h).
int runInfo(const QStringList &args, Context &ctx);
int runScan(const QStringList &args, Context &ctx);
int runRead(const QStringList &args, Context &ctx);
int runGet(const QStringList &args, Context &ctx);
int runSet(const QStringList &args, Context &ctx);
int runWrite(const QStringList &args, Context &ctx);
int runDiff(const QStringList &args, Context &ctx);
int runMonitor(const QStringList &args, Context &ctx);
// The tuning workbench: a test signal on a set value, analysed (cmd_test.cpp).
int runTest(const QStringList &args, Context &ctx);
// The reference fingerprint: save the settings and a standard test set, compare
// (cmd_reference.cpp).
int runReference(const QStringList &args, Context &ctx);

// The commissioning report of a node or a parameter file (cmd_report.cpp).
int runReport(const QStringList &args, Context &ctx);

// Module-fold PLC plan: cmd_fold.cpp.
int runFold(const QStringList &args, Context &ctx);

} // namespace vt::cli
