// HostError: why valvetune-sim cannot serve — the exit code (app/cli/exit_codes.h: 2 for a
// device the options cannot build, 3 for I/O) and one line for stderr.
#pragma once

#include <string>

namespace vt::simapp {

struct HostError
{
    int exitCode = 1;
    std::string message;
};

} // namespace vt::simapp
