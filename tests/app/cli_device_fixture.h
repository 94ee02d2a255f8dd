// Golden-test helpers for valvetune-cli's device commands (issue #6 "CLI"): runCli in-process
// with string streams against the built-in simulator, which keeps its parameters between the
// commands of one test (app/cli/sim_memory.h) and starts fresh in every test.
#pragma once

#include "app/cli/cli_app.h"
#include "app/cli/sim_memory.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace vt::clitest {

struct CliRun
{
    int code = -1;
    std::string out;
    std::string err;

    nlohmann::json json() const
    {
        auto doc = nlohmann::json::parse(out, nullptr, false);
        EXPECT_FALSE(doc.is_discarded()) << out << err;
        return doc;
    }
    bool says(const std::string &text) const { return out.find(text) != std::string::npos; }
    bool complains(const std::string &text) const { return err.find(text) != std::string::npos; }
    // One line on stderr, as every usage and device error is.
    int errLines() const
    {
        int n = 0;
        for (char c : err)
            n += c == '\n';
        return n;
    }
};

inline CliRun cli(QStringList args)
{
    args.prepend(QStringLiteral("valvetune-cli"));
    std::ostringstream out, err;
    CliRun r;
    r.code = cli::runCli(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

inline std::string what(const CliRun &r)
{
    return "exit " + std::to_string(r.code) + "\nstdout:\n" + r.out + "stderr:\n" + r.err;
}

class CliDevice : public ::testing::Test
{
protected:
    void SetUp() override { cli::forgetSimulators(); }
    void TearDown() override { cli::forgetSimulators(); }
};

} // namespace vt::clitest
