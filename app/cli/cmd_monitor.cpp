// valvetune-cli monitor CONNECTION [NAME...] [--rate HZ] [--duration S] [--csv] [--module ADDRESS]
// [--lang en|de] [--json]: poll display values of one module (default: d1.07..d1.13, one request
// on HCS) at the requested rate for the given time (MonitorScheduler), print each sample, and
// report the requested against the achieved rate at the end (on stderr with --csv, so the CSV
// stays clean). --rate 0: as fast as the link allows.
#include "commands.h"
#include "device_run.h"
#include "dict/cooking.h"
#include "model/monitor/monitor_scheduler.h"

#include <QElapsedTimer>
#include <QTimer>
#include <cstdio>
#include <iomanip>

namespace vt::cli {

namespace {

const char kName[] = "monitor";
const char kSynopsis[] = "monitor CONNECTION [NAME...] [--rate HZ] [--duration S] [--csv] "
                         "[--module ADDRESS] [--lang en|de] [--json]";
constexpr double kDefaultRate = 10;
constexpr double kDefaultDuration = 5;
constexpr double kMaxDuration = 24 * 3600;

std::optional<double> parseNumber(const QString &text, double min, double max)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !(v >= min && v <= max))
        return std::nullopt;
    return v;
}

} // namespace

int runMonitor(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    const bool csv = takeFlag(args, QStringLiteral("--csv"));
    bool missing = false;
    const auto rateArg = takeOption(args, QStringLiteral("--rate"), &missing);
    const auto durationArg = takeOption(args, QStringLiteral("--duration"), &missing);
    if (missing)
        return failUsage(ctx, kName, "--rate and --duration need a value");
    const auto rate =
        rateArg ? parseNumber(*rateArg, 0, 10'000) : std::optional<double>(kDefaultRate);
    if (!rate)
        return failUsage(ctx, kName,
                         "--rate takes samples per second 0..10000 (0: as fast as possible)");
    const auto duration = durationArg ? parseNumber(*durationArg, 0.01, kMaxDuration)
                                      : std::optional(kDefaultDuration);
    if (!duration)
        return failUsage(ctx, kName, "--duration takes seconds, more than 0");
    if (csv && ctx.json)
        return failUsage(ctx, kName, "--csv and --json exclude each other");
    if (!checkPositional(args, ctx, kName, 0, 64, &code))
        return code;

    DeviceRun run(ctx, *options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    const int address = module->address;
    auto named = readableRowsNamed(args, *module, ctx, kName, &code);
    if (!named)
        return code;
    std::vector<const dev::ParamMeta *> rows = std::move(*named);
    if (rows.empty())
        rows = model::defaultMonitorRows(*module->dictionary, module->identification.mode);
    if (rows.empty())
        return ctx.fail(kExitUsage, module->identification.family +
                                        " has no display values to monitor; name some");

    const dev::Language lang = run.lang();
    if (csv) {
        ctx.out << "time_s";
        for (const dev::ParamMeta *row : rows)
            ctx.out << ',' << row->name << (row->unit.empty() ? "" : " [" + row->unit + "]");
        ctx.out << '\n';
    }
    Json data = Json::array();
    double t0 = -1;   // session time of the first sample
    double tLast = 0; // of the last one, from t0
    std::string lastFailure;
    model::MonitorScheduler scheduler(run.access());
    QObject::connect(
        &scheduler, &model::MonitorScheduler::sampled, &scheduler,
        [&](const model::MonitorSample &s) {
            if (t0 < 0)
                t0 = s.seconds;
            const double t = s.seconds - t0;
            tLast = t;
            if (ctx.json) {
                Json raw = Json::array(), display = Json::array();
                for (std::size_t i = 0; i < s.rows.size(); ++i) {
                    raw.push_back(rawJson(s.values[i]));
                    display.push_back(
                        dev::isText(s.values[i])
                            ? Json(displayOf(*s.rows[i], s.values[i], lang))
                            : Json(dev::toDisplay(*s.rows[i], dev::rawNumber(s.values[i]))));
                }
                data.push_back(Json{{"t", t}, {"raw", raw}, {"display", display}});
            } else if (csv) {
                ctx.out << fixed(t, 4);
                for (std::size_t i = 0; i < s.rows.size(); ++i)
                    ctx.out << ','
                            << dev::formatNumber(*s.rows[i], dev::rawNumber(s.values[i]),
                                                 dev::Language::English);
                ctx.out << '\n';
            } else {
                ctx.out << std::right << std::setw(9) << fixed(t, 3) << " s";
                for (std::size_t i = 0; i < s.rows.size(); ++i)
                    ctx.out << "  " << s.rows[i]->name << ' '
                            << displayOf(*s.rows[i], s.values[i], lang);
                ctx.out << '\n';
            }
        });
    QObject::connect(&scheduler, &model::MonitorScheduler::pollFailed, &scheduler,
                     [&](int, const QString &reason) { lastFailure = str(reason); });

    bool over = false;
    QTimer end;
    end.setSingleShot(true);
    QObject::connect(&end, &QTimer::timeout, &end, [&] {
        over = true;
        run.wake();
    });
    const auto durationMs = std::chrono::milliseconds(static_cast<long long>(*duration * 1000.0));
    QElapsedTimer elapsed;
    scheduler.setModule(address, rows, *rate);
    elapsed.start();
    scheduler.start();
    end.start(durationMs);
    run.waitUntil([&] { return over; }, durationMs + DeviceRun::kStepLimit, true);
    scheduler.stop();
    const double seconds = static_cast<double>(elapsed.nsecsElapsed()) * 1e-9;

    const quint64 samples = scheduler.samples(address);
    // Between the first and the last sample: n samples span n - 1 periods.
    const double achieved =
        samples >= 2 && tLast > 0 ? static_cast<double>(samples - 1) / tLast : 0;
    if (ctx.json) {
        Json names = Json::array();
        for (const dev::ParamMeta *row : rows)
            names.push_back(Json{{"name", row->name}, {"unit", row->unit}});
        ctx.out << Json{{"module", moduleJson(*module)},
                        {"rows", names},
                        {"requested_hz", *rate},
                        {"achieved_hz", achieved},
                        {"duration_s", seconds},
                        {"samples", samples},
                        {"skipped", scheduler.skipped(address)},
                        {"failed", scheduler.failed(address)},
                        {"data", data}}
                       .dump(2)
                << '\n';
    } else {
        std::ostream &report = csv ? ctx.err : ctx.out;
        report << (csv ? "# " : "") << "requested "
               << (*rate > 0 ? fixed(*rate, 1) + " Hz" : "as fast as possible") << ", achieved "
               << fixed(achieved, 1) << " Hz (" << samples << " samples in " << fixed(seconds, 2)
               << " s, " << scheduler.skipped(address) << " skipped, " << scheduler.failed(address)
               << " failed)\n";
    }
    if (run.linkLost())
        return ctx.fail(kExitConnection, "the link was lost: " + str(run.lostReason()));
    if (samples == 0)
        return ctx.fail(kExitDeviceError,
                        "no sample arrived" + (lastFailure.empty() ? "" : ": " + lastFailure));
    return kExitOk;
}

} // namespace vt::cli
