// valvetune-cli test step|square|triangle|sine|sweep CONNECTION [--module A] [--branch 1|2] …:
// the tuning workbench on the command line (model/tuning). The signal drives the branch's bus set
// value (HCS A1.01 / A2.01, Wandfluh the dictionary's set value); its whole range is checked
// against the row's limits before anything is sent, and the test passes the confirmation gate
// (confirm_gate.h) with what it will do, including switching the set-value source (E17 = 2) when
// the module needs it. At the end, or when the travel window, the device, the link or Ctrl+C stops
// it, the set value and its source are written back and verified. The result: the step figures
// or gain and phase per frequency (run_analysis.h), as text or --json, and the recording as CSV.
// Exit codes: 0 done and restored, 1 aborted (says why and what was restored), 2 usage or
// refused before anything was sent, 3 link lost, 4 the restore did not verify.
#include "commands.h"
#include "confirm_gate.h"
#include "device_run.h"
#include "dict/cooking.h"
#include "model/monitor/set_value_step.h"
#include "model/tuning/run_analysis.h"
#include "model/tuning/test_run.h"
#include "model/tuning/workbench_rows.h"

#include <QLocale>
#include <QTimer>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>

namespace vt::cli {

namespace {

const char kName[] = "test";
const char kSynopsis[] =
    "test step|square|triangle|sine|sweep CONNECTION [--module ADDRESS] [--branch 1|2] [--yes]\n"
    "     [--rate HZ] [--window V] [--csv FILE] [--lang en|de] [--json]\n"
    "  step:     --from V --to V [--hold S] [--repeat N] [--direction up|down|both]\n"
    "  square, triangle, sine:  --amplitude V --offset V --frequency HZ --cycles N [--settling N]\n"
    "  sweep:    --amplitude V --offset V --from-hz F --to-hz F [--points-per-decade N]\n"
    "            [--cycles N] [--settling N]\n"
    "  Values in the set value's display unit, in the --lang notation (German: 1,5).\n"
    "  --rate     write + read cycles per second (default: as fast as the link allows)\n"
    "  --window   stop when the actual value leaves the signal's range by more than V\n"
    "  --yes      start without asking (the test moves the actuator)";

std::atomic<bool> g_interrupted{false};

extern "C" void onInterrupt(int)
{
    g_interrupted = true;
}

struct Parsed
{
    model::SignalSpec spec;
    std::optional<double> window;
    double rate = 0;
    int branch = 1;
    QString csv;
};

// Reads the signal's options; an error message when one is missing or wrong.
std::string parseSignal(QStringList &args, dev::Language lang, Parsed &p)
{
    bool missing = false;
    std::string error;
    const auto take = [&](const char *name) {
        return takeOption(args, QString::fromLatin1(name), &missing);
    };
    const auto decimal = [&](const char *name, double *into, bool required) {
        const auto text = take(name);
        if (!text) {
            if (required && error.empty())
                error = std::string(name) + " is needed for this signal";
            return;
        }
        const auto v = parseDecimal(*text, lang);
        if (!v && error.empty())
            error = std::string(name) + " takes a number" +
                    (lang == dev::Language::German ? " (German notation: 1,5)" : " (1.5)") +
                    ", got '" + str(*text) + "'";
        if (v)
            *into = *v;
    };
    const auto integer = [&](const char *name, int *into, int min, int max) {
        const auto text = take(name);
        if (!text)
            return;
        const auto v = parseInteger(*text, min, max);
        if (!v && error.empty())
            error = std::string(name) + " takes a whole number " + std::to_string(min) + ".." +
                    std::to_string(max);
        if (v)
            *into = static_cast<int>(*v);
    };
    model::SignalSpec &s = p.spec;
    switch (s.kind) {
    case model::SignalKind::Step: {
        decimal("--from", &s.from, true);
        decimal("--to", &s.to, true);
        decimal("--hold", &s.hold, false);
        integer("--repeat", &s.repeats, 1, 1000);
        if (const auto d = take("--direction")) {
            const auto direction = dev::fromKey<model::StepDirection>(str(*d));
            if (!direction && error.empty())
                error = "--direction takes up, down or both";
            if (direction)
                s.direction = *direction;
        }
        break;
    }
    case model::SignalKind::Square:
    case model::SignalKind::Triangle:
    case model::SignalKind::Sine:
        decimal("--amplitude", &s.amplitude, true);
        decimal("--offset", &s.offset, true);
        decimal("--frequency", &s.frequencyHz, true);
        integer("--cycles", &s.cycles, 1, 10'000);
        s.settlingCycles = 1;
        integer("--settling", &s.settlingCycles, 0, 10'000);
        break;
    case model::SignalKind::Sweep:
        decimal("--amplitude", &s.amplitude, true);
        decimal("--offset", &s.offset, true);
        decimal("--from-hz", &s.fromHz, true);
        decimal("--to-hz", &s.toHz, true);
        integer("--points-per-decade", &s.pointsPerDecade, 1, 50);
        integer("--cycles", &s.cycles, 1, 10'000);
        integer("--settling", &s.settlingCycles, 0, 10'000);
        break;
    }
    double window = 0;
    bool hasWindow = false;
    if (args.contains(QStringLiteral("--window"))) {
        decimal("--window", &window, true);
        hasWindow = true;
    }
    if (hasWindow)
        p.window = window;
    decimal("--rate", &p.rate, false);
    integer("--branch", &p.branch, 1, 2);
    if (const auto csv = take("--csv"))
        p.csv = *csv;
    if (missing && error.empty())
        error = "an option is missing its value";
    if (error.empty() && p.rate < 0)
        error = "--rate takes cycles per second, 0 or more (0: as fast as the link allows)";
    return error;
}

// The recording as CSV: each channel sample with the set value acknowledged by then.
bool writeCsv(const QString &path, const model::TestRecording &r, const dev::ParamMeta &setValueRow)
{
    std::ofstream out(path.toStdString());
    if (!out)
        return false;
    const auto unit = [](const dev::ParamMeta &row) {
        return row.unit.empty() ? std::string() : " [" + row.unit + "]";
    };
    out << "time_s," << setValueRow.name << " written" << unit(setValueRow);
    for (const dev::ParamMeta *row : r.rows)
        out << ',' << row->name << unit(*row);
    out << '\n';
    const std::size_t n = r.channels.empty() ? 0 : r.channels.front().t.size();
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = r.channels.front().t[i];
        while (k + 1 < r.setValue.t.size() && r.setValue.t[k + 1] <= t)
            ++k;
        out << fixed(t, 6) << ','
            << (r.setValue.y.empty() ? std::string() : fixed(r.setValue.y[k], 6));
        for (const model::Samples &c : r.channels)
            out << ',' << (i < c.y.size() ? fixed(c.y[i], 6) : std::string());
        out << '\n';
    }
    return static_cast<bool>(out);
}

Json stepJson(const model::StepResult &s)
{
    Json j{{"direction", s.edge.to > s.edge.from ? "up" : "down"},
           {"from", s.edge.from},
           {"to", s.edge.to},
           {"time_s", s.edge.time}};
    if (s.metrics) {
        const model::StepMetrics &m = *s.metrics;
        j["dead_time_s"] = numberOrNull(m.deadTime);
        j["rise_time_s"] = numberOrNull(m.riseTime);
        j["overshoot_pct"] = numberOrNull(m.overshootPct);
        j["peak_time_s"] = numberOrNull(m.peakTime);
        j["settling_time_2pct_s"] = numberOrNull(m.settlingTime2);
        j["settling_time_5pct_s"] = numberOrNull(m.settlingTime5);
        j["steady_state_error"] = numberOrNull(m.steadyStateError);
        j["final_value"] = numberOrNull(m.finalValue);
    } else if (s.problem) {
        j["problem"] = std::string(model::stepProblemKey(*s.problem));
    }
    return j;
}

void printSteps(std::ostream &out, const model::RunAnalysis &a, const dev::ParamMeta &row)
{
    const std::string unit = row.unit.empty() ? std::string() : " " + row.unit;
    for (const model::StepResult &s : a.steps) {
        out << (s.edge.to > s.edge.from ? "step up   " : "step down ") << fixed(s.edge.from, 3)
            << " -> " << fixed(s.edge.to, 3) << unit << " at " << fixed(s.edge.time, 3) << " s: ";
        if (!s.metrics) {
            out << "no figures (" << (s.problem ? model::stepProblemKey(*s.problem) : "?") << ")\n";
            continue;
        }
        const model::StepMetrics &m = *s.metrics;
        out << "dead time " << fixed(m.deadTime, 3) << " s, rise time " << fixed(m.riseTime, 3)
            << " s, overshoot " << fixed(m.overshootPct, 1) << " %, peak " << fixed(m.peakTime, 3)
            << " s, settling 2 % " << fixed(m.settlingTime2, 3) << " s / 5 % "
            << fixed(m.settlingTime5, 3) << " s, steady-state error "
            << fixed(m.steadyStateError, 3) << unit << '\n';
    }
}

void printPoints(std::ostream &out, const model::RunAnalysis &a)
{
    out << "frequency_hz  gain_db  phase_deg  quality  valid\n";
    for (const model::FrequencyPoint &p : a.points)
        out << fixed(p.frequencyHz, 3) << "  " << fixed(p.gainDb, 2) << "  " << fixed(p.phaseDeg, 1)
            << "  " << fixed(p.quality, 3) << "  "
            << (p.valid ? "yes"
                        : std::string("no (") + std::string(model::frequencyProblemKey(p.problem)) +
                              ")")
            << '\n';
    out << "-3 dB at " << (a.f3dB ? fixed(*a.f3dB, 2) + " Hz" : std::string("- (not reached)"))
        << ", -90 deg at "
        << (a.f90deg ? fixed(*a.f90deg, 2) + " Hz" : std::string("- (not reached)"))
        << "; valid up to " << fixed(a.maxValidHz, 2) << " Hz\n";
}

std::string restoredText(const model::TestOutcome &o, dev::Language lang)
{
    if (o.restore.empty())
        return "nothing to restore";
    std::string text;
    for (const model::WriteItem &item : o.restore) {
        text += (text.empty() ? "" : "; ") + item.row->name + " back to " +
                displayOf(*item.row, item.value, lang) + " (" +
                str(model::writeStatusText(item.status)) + ")";
    }
    return text;
}

} // namespace

int runTest(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    ConfirmGate gate(ctx, args);
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    if (args.isEmpty())
        return failUsage(ctx, kName, "name the signal: step, square, triangle, sine or sweep");
    const auto kind = dev::fromKey<model::SignalKind>(str(args.takeFirst()));
    if (!kind)
        return failUsage(ctx, kName, "the signal is step, square, triangle, sine or sweep");
    Parsed p;
    p.spec.kind = *kind;
    if (const std::string error = parseSignal(args, options->lang, p); !error.empty())
        return failUsage(ctx, kName, error);
    if (!checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    std::string why;
    const auto signal = model::TestSignal::make(p.spec, &why);
    if (!signal)
        return failUsage(ctx, kName, why);

    DeviceRun run(ctx, *options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    const dev::Dictionary &dict = *module->dictionary;
    const std::string &mode = module->identification.mode;
    const dev::ParamMeta *setValue = model::testSetValueRow(dict, mode, p.branch);
    if (!setValue) {
        const dev::LocalText reason = dict.monitor.forMode(mode).noSetValue;
        return ctx.fail(kExitUsage,
                        moduleText(*module) + " has no set value for branch " +
                            std::to_string(p.branch) + " a test can drive" +
                            (reason.in(run.lang()).empty() ? "" : ": " + reason.in(run.lang())) +
                            "; nothing was sent");
    }
    model::TestRunSetup setup = model::TestRun::setupFor(*module, *setValue, *signal);
    setup.window = p.window;
    setup.rateHz = p.rate;
    setup.origin = model::AuditOrigin::CliTest;
    setup.switchSource = true; // the confirmation below lists the source rows
    if (const QString problem = model::TestRun::rangeProblem(setup); !problem.isEmpty())
        return ctx.fail(kExitUsage, str(problem) + "; nothing was sent");

    // The gate shows what the test does: the set value's range and every source row it switches.
    const auto rules = model::SetValueStep::activationRules(dict, mode);
    std::vector<GateItem> gated;
    const dev::RawValue highest{model::setValueRaw(*setValue, signal->maximum())};
    const dev::RawValue lowest{model::setValueRaw(*setValue, signal->minimum())};
    gated.push_back({&*module, setValue, highest, {}});
    gated.push_back({&*module, setValue, lowest, {}});
    for (const dev::SetValueActivation *rule : rules)
        gated.push_back({&*module,
                         model::SetValueStep::ruleWriteRow(dict, *rule),
                         dev::RawValue{rule->value},
                         {}});
    const std::string what =
        std::string("a ") + key(*kind) + " test of " + fixed(signal->duration(), 1) + " s on " +
        setValue->name + " between " + displayOf(*setValue, lowest, run.lang()) + " and " +
        displayOf(*setValue, highest, run.lang()) + "; afterwards everything is written back";
    if (const int c = gate.pass(run, std::move(gated), what))
        return c;

    model::TestRun test(run.access(), setup);
    std::optional<model::TestOutcome> outcome;
    QObject::connect(&test, &model::TestRun::finished, &test, [&](const model::TestOutcome &o) {
        outcome = o;
        run.wake();
    });
    g_interrupted = false;
    const auto previous = std::signal(SIGINT, onInterrupt);
    QTimer interrupt;
    QObject::connect(&interrupt, &QTimer::timeout, &test, [&] {
        if (g_interrupted)
            test.stop();
    });
    interrupt.start(50);
    test.start();
    const auto limit =
        std::chrono::milliseconds(static_cast<long long>(signal->duration() * 1000)) +
        DeviceRun::kStepLimit;
    run.waitUntil([&] { return outcome.has_value(); }, limit, true);
    interrupt.stop();
    std::signal(SIGINT, previous);
    if (!outcome) {
        test.stop();
        run.waitUntil([&] { return outcome.has_value(); }, DeviceRun::kStepLimit, true);
    }
    if (!outcome)
        return run.failDeadline("module " + std::to_string(module->address) + ": the test");

    const model::TestRecording &rec = test.recording();
    const model::RunAnalysis analysis = model::analyseRun(*signal, rec, setup.actualRow, setValue);
    if (!p.csv.isEmpty() && !writeCsv(p.csv, rec, *setValue))
        ctx.err << "valvetune-cli: could not write " << str(p.csv) << '\n';

    const bool periodic = !signal->points().empty();
    if (ctx.json) {
        Json j{{"module", moduleJson(*module)},
               {"signal", key(*kind)},
               {"set_value", setValue->name},
               {"actual", setup.actualRow ? Json(setup.actualRow->name) : Json(nullptr)},
               {"end", key(outcome->end)},
               {"update_hz", rec.updateRateHz()},
               {"sample_hz", rec.sampleRateHz()},
               {"restored", outcome->restored}};
        if (!outcome->reason.isEmpty())
            j["reason"] = str(outcome->reason);
        Json runs = Json::array();
        for (const model::StepResult &s : analysis.steps)
            runs.push_back(stepJson(s));
        if (!analysis.steps.empty() || !periodic)
            j["runs"] = runs;
        if (periodic) {
            Json points = Json::array();
            for (const model::FrequencyPoint &pt : analysis.points) {
                Json q{{"frequency_hz", pt.frequencyHz},
                       {"gain_db", numberOrNull(pt.gainDb)},
                       {"phase_deg", numberOrNull(pt.phaseDeg)},
                       {"quality", numberOrNull(pt.quality)},
                       {"valid", pt.valid}};
                if (!pt.valid)
                    q["problem"] = std::string(model::frequencyProblemKey(pt.problem));
                points.push_back(q);
            }
            j["points"] = points;
            j["f_3db_hz"] = analysis.f3dB ? Json(*analysis.f3dB) : Json(nullptr);
            j["f_90deg_hz"] = analysis.f90deg ? Json(*analysis.f90deg) : Json(nullptr);
            j["valid_below_hz"] = analysis.maxValidHz;
        }
        ctx.out << j.dump(2) << '\n';
    } else {
        ctx.out << moduleText(*module) << ": " << key(*kind) << " on " << setValue->name
                << ", response "
                << (setup.actualRow ? setup.actualRow->name : std::string("(none named)")) << "; "
                << rec.writes << " set values written at " << fixed(rec.updateRateHz(), 1)
                << " Hz, " << rec.cycles << " samples at " << fixed(rec.sampleRateHz(), 1)
                << " Hz\n";
        printSteps(ctx.out, analysis, *setValue);
        if (periodic)
            printPoints(ctx.out, analysis);
        ctx.out << "restored: " << restoredText(*outcome, run.lang()) << '\n';
    }

    switch (outcome->end) {
    case model::TestEnd::Finished:
        if (!outcome->restored)
            return ctx.fail(exitCodeOf(outcome->restore, run.linkLost()),
                            "the set value was not restored: " +
                                restoredText(*outcome, run.lang()));
        return kExitOk;
    case model::TestEnd::Refused:
        return ctx.fail(outcome->needsSource ? kExitUsage : kExitDeviceError,
                        str(outcome->reason) + "; nothing was sent");
    case model::TestEnd::LinkLost:
        return ctx.fail(kExitConnection, "the test stopped: " + str(outcome->reason) + "; " +
                                             restoredText(*outcome, run.lang()));
    default:
        return ctx.fail(kExitDeviceError,
                        "the test stopped: " +
                            (outcome->reason.isEmpty() ? std::string("stopped by the user")
                                                       : str(outcome->reason)) +
                            "; " + restoredText(*outcome, run.lang()));
    }
}

} // namespace vt::cli
