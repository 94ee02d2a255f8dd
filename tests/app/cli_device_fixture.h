// Golden-test fixture for valvetune-cli's device commands: runCli in-process (cli_run.h) against
// the built-in simulator, which keeps its parameters between the
// commands of one test (app/cli/sim_memory.h) and starts fresh in every test.
#pragma once

#include "app/cli/sim_memory.h"
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace vt::clitest {

using test::cli;
using test::CliRun;
using test::what;

class CliDevice : public ::testing::Test
{
protected:
    void SetUp() override { cli::forgetSimulators(); }
    void TearDown() override { cli::forgetSimulators(); }
};

} // namespace vt::clitest
