// valvetune-cli run in-process for golden tests: runCli with string streams, the exit code and
// both outputs kept for the assertions.
#pragma once

#include "app/cli/cli_app.h"

#include <QStringList>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace vt::test {

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
    // The lines on stderr (one for every usage and device error).
    int errLines() const
    {
        int n = 0;
        for (char c : err)
            n += c == '\n';
        return n;
    }
};

// `args` without the program name.
inline CliRun cli(QStringList args)
{
    args.prepend(QStringLiteral("valvetune-cli"));
    std::ostringstream out, err;
    CliRun r;
    r.code = vt::cli::runCli(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

// Exit code and both outputs, for a failure message.
inline std::string what(const CliRun &r)
{
    return "exit " + std::to_string(r.code) + "\nstdout:\n" + r.out + "stderr:\n" + r.err;
}

} // namespace vt::test
