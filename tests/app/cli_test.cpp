// valvetune-cli conventions (Foundation issue): usage errors exit 2 with one line on stderr;
// --help and --version exit 0; --json output is JSON.
#include "app/cli/cli_app.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>

namespace {

struct CliRun
{
    int code;
    std::string out;
    std::string err;
};

CliRun cli(QStringList args)
{
    args.prepend("valvetune-cli");
    std::ostringstream out, err;
    const int code = vt::cli::runCli(args, out, err);
    return {code, out.str(), err.str()};
}

int lines(const std::string &s)
{
    int n = 0;
    for (char c : s)
        n += c == '\n';
    return n;
}

} // namespace

TEST(Cli, UsageErrorsExitTwoWithOneLineOnStderr)
{
    for (const QStringList &args : {QStringList{}, QStringList{"--frobnicate"}, QStringList{"no-such-command"},
                                    QStringList{"--json", "no-such-command"}}) {
        const CliRun r = cli(args);
        EXPECT_EQ(r.code, vt::cli::kExitUsage) << args.join(' ').toStdString();
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_EQ(r.err.rfind("valvetune-cli: ", 0), 0u) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
}

TEST(Cli, HelpAndVersion)
{
    const CliRun help = cli({"--help"});
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("Exit codes: 0 ok, 1 device or protocol error, 2 usage error"), std::string::npos);
    const CliRun version = cli({"--version"});
    EXPECT_EQ(version.code, 0);
    EXPECT_EQ(version.out, std::string("valvetune-cli ") + VT_VERSION + "\n");
    const CliRun json = cli({"--json", "--version"});
    const auto doc = nlohmann::json::parse(json.out);
    EXPECT_EQ(doc.at("version"), VT_VERSION);
}

TEST(Cli, TheInstalledBinaryKeepsTheExitCodes)
{
    const std::string cmd = std::string(VT_CLI_PATH) + " --frobnicate 2>/dev/null";
    FILE *p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::array<char, 256> buf{};
    while (fgets(buf.data(), static_cast<int>(buf.size()), p)) {
    }
    const int status = pclose(p);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
}
