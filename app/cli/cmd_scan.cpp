// valvetune-cli scan CONNECTION [--timeout MS] [--json]: which addresses answer. Modbus RTU tries
// units 1..32, Modbus TCP and the node image 0..32, HART poll addresses 0..15, CANopen nodes
// 1..127, each once with a short timeout; a simulator: its modules.
#include "commands.h"
#include "device_run.h"

namespace vt::cli {

namespace {

const char kName[] = "scan";
const char kSynopsis[] = "scan CONNECTION [--timeout MS] [--json]";
constexpr long long kDefaultTimeoutMs = 50; // per address, on top of the wire time

} // namespace

int runScan(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    bool missing = false;
    const auto timeoutArg = takeOption(args, QStringLiteral("--timeout"), &missing);
    if (missing)
        return failUsage(ctx, kName, "--timeout needs a value");
    long long timeoutMs = kDefaultTimeoutMs;
    if (timeoutArg) {
        const auto t = parseInteger(*timeoutArg, 1, 60'000);
        if (!t)
            return failUsage(ctx, kName, "--timeout takes milliseconds 1..60000");
        timeoutMs = *t;
    }
    if (!checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    options->spec.turnaround = std::chrono::milliseconds(timeoutMs);
    options->spec.retries = 0;
    DeviceRun run(ctx, *options);
    if (const int c = run.connect())
        return c;

    const std::vector<int> tried = run.connection().scanAddresses();
    const auto results = run.identifyEach(tried);
    Json found = Json::array();
    for (const model::IdentifyResult &r : results) {
        if (r.ok) {
            found.push_back(moduleJson(r.module));
            if (!ctx.json)
                ctx.out << moduleText(r.module, "address") << '\n';
        } else if (r.failure.status == model::OutcomeStatus::Ok) {
            // An answer that identifies no known device: something is there.
            found.push_back(Json{{"address", r.module.address},
                                 {"family", nullptr},
                                 {"error", str(model::identifyMessage(r, run.lang()))}});
            if (!ctx.json)
                ctx.out << "address " << r.module.address << ": answers, not identified: "
                        << str(model::identifyMessage(r, run.lang())) << '\n';
        }
    }
    if (run.linkLost())
        return ctx.fail(kExitConnection,
                        "the link was lost during the scan: " + str(run.lostReason()));
    if (ctx.json)
        ctx.out << Json{{"connection", str(run.connection().describe())},
                        {"tried", tried},
                        {"found", found}}
                       .dump(2)
                << '\n';
    else
        ctx.out << found.size() << " of " << tried.size() << " addresses answered\n";
    if (found.empty())
        return ctx.fail(kExitDeviceError, "no module answered");
    return kExitOk;
}

} // namespace vt::cli
