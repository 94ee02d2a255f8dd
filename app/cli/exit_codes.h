// Exit codes every valvetune-cli subcommand follows (scripts depend on them).
#pragma once

namespace vt::cli {

enum ExitCode : int {
    kExitOk = 0,
    kExitDeviceError = 1,  // device or protocol error (also: a frame that does not decode)
    kExitUsage = 2,        // the command line is wrong
    kExitConnection = 3,   // the link could not be opened or was lost
    kExitVerification = 4, // a written value did not read back as written
};

} // namespace vt::cli
