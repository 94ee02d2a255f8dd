// valvetune-cli reference save|compare …: the reference fingerprint on the command line
// (model/tuning/reference_*.h, docs/TUNING.md "Reference fingerprint"). `save` reads every
// setting of the module, runs the standard tests (steps up and down between centre − amplitude and
// centre + amplitude, optionally a stepped-sine sweep) and writes one .vtref file; `compare` reads
// such a file, refuses it for a module of another family or mode (saying why), repeats its tests
// with its specs and prints the settings that differ and each figure's drift against its limit.
// Both pass the confirmation gate (confirm_gate.h) once for the whole set, with the set value's
// range and the source rows they switch; after each test the set value and its source are written
// back and verified. Exit codes: 0 done and restored (compare: every figure within its limit),
// 1 a test stopped or (compare) a figure drifted beyond its limit, 2 usage or refused before
// anything was sent, 3 link lost, 4 the restore did not verify.
#include "commands.h"
#include "confirm_gate.h"
#include "device_run.h"
#include "dict/dictionary_loader.h"
#include "model/monitor/set_value_step.h"
#include "model/tuning/reference_session.h"
#include "model/tuning/workbench_rows.h"

#include <QTimer>
#include <atomic>
#include <csignal>

namespace vt::cli {

namespace {

const char kName[] = "reference";
const char kSynopsis[] =
    "reference save CONNECTION --out FILE.vtref --centre V --amplitude V [--hold S]\n"
    "     [--sweep --from-hz F --to-hz F [--points-per-decade N]] [--branch 1|2]\n"
    "reference compare FILE.vtref CONNECTION [--rise-time PCT] [--overshoot POINTS]\n"
    "     [--settling PCT] [--steady-state PCT] [--bandwidth PCT] [--phase-90 PCT]\n"
    "  both: [--module ADDRESS] [--rate HZ] [--window V] [--yes] [--lang en|de] [--json]\n"
    "  save: the settings and the tests into one file; the steps go from centre - amplitude\n"
    "        to centre + amplitude and back, each level held --hold s (default 1)\n"
    "  compare: the same tests again on the module at the file's address (or --module);\n"
    "        limits: rise time and settling +-20 %, overshoot +5 points, steady-state error\n"
    "        +-2 % of the step, bandwidth and -90 deg frequency +-20 %\n"
    "  --yes      start without asking (the tests move the actuator)";

std::atomic<bool> g_interrupted{false};

extern "C" void onReferenceInterrupt(int)
{
    g_interrupted = true;
}

struct Options
{
    QString out;
    model::ReferencePlan plan;
    int branch = 1;
    double rate = 0;
    std::optional<double> window;
    model::DriftThresholds limits;
};

// The options of `save` or `compare`; an error message when one is missing or wrong.
std::string parseOptions(QStringList &args, dev::Language lang, bool save, Options &o)
{
    bool missing = false;
    std::string error;
    const auto decimal = [&](const char *name, double *into, bool required) {
        const auto text = takeOption(args, QString::fromLatin1(name), &missing);
        if (!text) {
            if (required && error.empty())
                error = std::string(name) + " is needed";
            return false;
        }
        const auto v = parseDecimal(*text, lang);
        if (!v && error.empty())
            error = std::string(name) + " takes a number" +
                    (lang == dev::Language::German ? " (German notation: 1,5)" : " (1.5)") +
                    ", got '" + str(*text) + "'";
        if (v)
            *into = *v;
        return v.has_value();
    };
    if (save) {
        if (const auto out = takeOption(args, QStringLiteral("--out"), &missing))
            o.out = *out;
        else if (error.empty())
            error = "--out FILE.vtref is needed";
        decimal("--centre", &o.plan.centre, true);
        decimal("--amplitude", &o.plan.amplitude, true);
        decimal("--hold", &o.plan.hold, false);
        o.plan.sweep = args.removeAll(QStringLiteral("--sweep")) > 0;
        decimal("--from-hz", &o.plan.fromHz, o.plan.sweep);
        decimal("--to-hz", &o.plan.toHz, o.plan.sweep);
        if (const auto n = takeOption(args, QStringLiteral("--points-per-decade"), &missing)) {
            const auto v = parseInteger(*n, 1, 50);
            if (!v && error.empty())
                error = "--points-per-decade takes a whole number 1..50";
            if (v)
                o.plan.pointsPerDecade = static_cast<int>(*v);
        }
        if (const auto b = takeOption(args, QStringLiteral("--branch"), &missing)) {
            const auto v = parseInteger(*b, 1, 2);
            if (!v && error.empty())
                error = "--branch takes 1 or 2";
            if (v)
                o.branch = static_cast<int>(*v);
        }
        if (error.empty() && !(o.plan.amplitude > 0))
            error = "--amplitude must be more than 0";
    } else {
        decimal("--rise-time", &o.limits.riseTimePct, false);
        decimal("--overshoot", &o.limits.overshootPoints, false);
        decimal("--settling", &o.limits.settlingPct, false);
        decimal("--steady-state", &o.limits.steadyStatePctOfStep, false);
        decimal("--bandwidth", &o.limits.bandwidthPct, false);
        decimal("--phase-90", &o.limits.phase90Pct, false);
    }
    double window = 0;
    if (decimal("--window", &window, false))
        o.window = window;
    decimal("--rate", &o.rate, false);
    if (missing && error.empty())
        error = "an option is missing its value";
    if (error.empty() && o.rate < 0)
        error = "--rate takes cycles per second, 0 or more (0: as fast as the link allows)";
    return error;
}

// Runs the set after the gate; the session when it ran (complete or not), else nullopt after
// printing why (*code).
std::unique_ptr<model::ReferenceSession> runSet(DeviceRun &run, ConfirmGate &gate,
                                                model::ReferenceSetup setup, int *code)
{
    Context &ctx = run.ctx();
    if (const QString problem = model::ReferenceSession::setupProblem(setup); !problem.isEmpty()) {
        *code = ctx.fail(kExitUsage, str(problem) + "; nothing was sent");
        return nullptr;
    }
    const dev::Dictionary &dict = *setup.module.dictionary;
    const dev::ParamMeta &row = *setup.setValueRow;
    double lo = INFINITY;
    double hi = -INFINITY;
    for (const model::ReferenceTestSpec &t : setup.tests)
        if (const auto signal = model::TestSignal::make(t.spec)) {
            lo = std::min(lo, signal->minimum());
            hi = std::max(hi, signal->maximum());
        }
    // The gate shows what the set does: the set value's range and every source row it switches.
    const dev::RawValue highest{model::setValueRaw(row, hi)};
    const dev::RawValue lowest{model::setValueRaw(row, lo)};
    std::vector<GateItem> gated{{&setup.module, &row, highest, {}},
                                {&setup.module, &row, lowest, {}}};
    for (const dev::SetValueActivation *rule :
         model::SetValueStep::activationRules(dict, setup.module.identification.mode))
        gated.push_back({&setup.module,
                         model::SetValueStep::ruleWriteRow(dict, *rule),
                         dev::RawValue{rule->value},
                         {}});
    const std::string what =
        "a reference test set (" + std::to_string(setup.tests.size()) + " test(s), about " +
        fixed(model::ReferenceSession::duration(setup), 0) + " s) on " + row.name + " between " +
        displayOf(row, lowest, run.lang()) + " and " + displayOf(row, highest, run.lang()) +
        "; afterwards everything is written back";
    if ((*code = gate.pass(run, std::move(gated), what)) != kExitOk)
        return nullptr;
    setup.switchSource = true; // the confirmation listed the source rows

    auto session = std::make_unique<model::ReferenceSession>(run.access(), setup);
    bool done = false;
    QObject::connect(session.get(), &model::ReferenceSession::finished, session.get(), [&] {
        done = true;
        run.wake();
    });
    g_interrupted = false;
    const auto previous = std::signal(SIGINT, onReferenceInterrupt);
    QTimer interrupt;
    QObject::connect(&interrupt, &QTimer::timeout, session.get(), [&] {
        if (g_interrupted)
            session->stop();
    });
    interrupt.start(50);
    session->start();
    const auto limit = std::chrono::milliseconds(static_cast<long long>(
                           model::ReferenceSession::duration(setup) * 1000)) +
                       DeviceRun::kStepLimit;
    run.waitUntil([&] { return done; }, limit, true);
    interrupt.stop();
    std::signal(SIGINT, previous);
    if (!done) {
        session->stop();
        run.waitUntil([&] { return done; }, DeviceRun::kStepLimit, true);
    }
    if (!done) {
        *code = run.failDeadline("module " + std::to_string(setup.module.address) +
                                 ": the reference tests");
        return nullptr;
    }
    if (!session->complete()) {
        const model::TestOutcome &o = session->lastOutcome();
        *code = ctx.fail(run.linkLost() || o.end == model::TestEnd::LinkLost ? kExitConnection
                         : !o.restore.empty() && !o.restored ? exitCodeOf(o.restore, run.linkLost())
                                                             : kExitDeviceError,
                         str(session->statusText()));
        return nullptr;
    }
    return session;
}

int save(QStringList &args, Context &ctx, ConfirmGate &gate, const DeviceOptions &options)
{
    Options o;
    if (const std::string error = parseOptions(args, options.lang, true, o); !error.empty())
        return failUsage(ctx, kName, error);
    int code = kExitOk;
    if (!checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    DeviceRun run(ctx, options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    const dev::ParamMeta *setValue =
        model::testSetValueRow(*module->dictionary, module->identification.mode, o.branch);
    if (!setValue)
        return ctx.fail(kExitUsage, moduleText(*module) + " has no set value for branch " +
                                        std::to_string(o.branch) +
                                        " a test can drive; nothing was sent");
    model::ReferenceSetup setup;
    setup.module = *module;
    setup.setValueRow = setValue;
    setup.tests = model::referenceTests(o.plan);
    setup.rateHz = o.rate;
    setup.window = o.window;
    auto session = runSet(run, gate, setup, &code);
    if (!session)
        return code;
    const model::Reference reference = model::makeReference(
        *module, *setValue, o.plan, session->settings(), session->runs(), run.lang());
    if (const QString error = model::saveReference(reference, o.out); !error.isEmpty())
        return ctx.fail(kExitUsage, str(error));
    if (ctx.json) {
        Json figures = Json::array();
        for (const model::ReferenceFigure &f : reference.file.figures)
            figures.push_back({{"test", f.test},
                               {"metric", f.metric},
                               {"value", numberOrNull(f.value)},
                               {"unit", f.unit}});
        ctx.out << Json{{"module", moduleJson(*module)},
                        {"file", str(o.out)},
                        {"settings", reference.file.settings.size()},
                        {"tests", reference.file.tests.size()},
                        {"figures", figures},
                        {"restored", true}}
                       .dump(2)
                << '\n';
    } else {
        ctx.out << moduleText(*module) << ": reference saved to " << str(o.out) << " ("
                << reference.file.settings.size() << " settings, " << reference.file.tests.size()
                << " test(s))\n";
        for (const model::ReferenceFigure &f : reference.file.figures)
            ctx.out << "  " << f.test << ' ' << f.metric << ' ' << fixed(f.value, 3) << ' '
                    << f.unit << '\n';
        ctx.out << "restored: the set value after each test\n";
    }
    return kExitOk;
}

int compare(QStringList &args, Context &ctx, ConfirmGate &gate, DeviceOptions options)
{
    if (args.isEmpty() || args.first().startsWith(QLatin1String("--")))
        return failUsage(ctx, kName, "name the reference file: compare FILE.vtref");
    const QString path = args.takeFirst();
    Options o;
    if (const std::string error = parseOptions(args, options.lang, false, o); !error.empty())
        return failUsage(ctx, kName, error);
    int code = kExitOk;
    if (!checkPositional(args, ctx, kName, 0, 0, &code))
        return code;
    QString why;
    const auto reference = model::loadReference(path, *dev::builtinDictionaries(), &why);
    if (!reference)
        return ctx.fail(kExitUsage, str(why));
    if (!options.module)
        options.module = reference->file.address;
    DeviceRun run(ctx, options);
    auto module = run.connectFirstModule(&code);
    if (!module)
        return code;
    if (const QString problem = model::referenceFitProblem(reference->file, *module);
        !problem.isEmpty()) {
        std::string reason = str(problem);
        if (!reason.empty() && reason.back() == '.')
            reason.pop_back();
        return ctx.fail(kExitUsage, "the reference does not fit: " + reason + "; nothing was sent");
    }
    for (const QString &note : model::referenceNotes(reference->file, *module))
        ctx.err << "valvetune-cli: note: " << str(note) << '\n';
    model::ReferenceSetup setup;
    setup.module = *module;
    setup.setValueRow = module->dictionary->find(reference->file.setValue);
    setup.tests = reference->tests();
    setup.rateHz = o.rate;
    setup.window = o.window;
    auto session = runSet(run, gate, setup, &code);
    if (!session)
        return code;
    const model::ReferenceComparison c = model::compareWithReference(
        *reference, session->runs(), session->settings(), o.limits, run.lang());
    if (ctx.json) {
        Json params = Json::array();
        for (const model::ParamDrift &p : c.params)
            params.push_back({{"module", p.module},
                              {"row", p.row},
                              {"name", p.name},
                              {"reference", p.reference ? Json(*p.reference) : Json(nullptr)},
                              {"now", p.now ? Json(*p.now) : Json(nullptr)},
                              {"unit", p.unit}});
        Json metrics = Json::array();
        for (const model::MetricDrift &m : c.metrics)
            metrics.push_back({{"module", m.module},
                               {"test", m.test},
                               {"metric", std::string(model::driftMetricKey(m.metric))},
                               {"reference", numberOrNull(m.reference)},
                               {"now", numberOrNull(m.now)},
                               {"unit", m.unit},
                               {"delta_pct", numberOrNull(m.deltaPercent)},
                               {"threshold_pct", m.thresholdPercent},
                               {"exceeded", m.exceeded}});
        ctx.out << Json{{"module", moduleJson(*module)},
                        {"file", str(path)},
                        {"params", params},
                        {"metrics", metrics},
                        {"exceeded", c.exceeded()},
                        {"restored", true}}
                       .dump(2)
                << '\n';
    } else {
        ctx.out << moduleText(*module) << ": compared with " << str(path) << '\n';
        ctx.out << "settings that differ: " << (c.params.empty() ? "none" : "") << '\n';
        for (const model::ParamDrift &p : c.params)
            ctx.out << "  " << p.row << " (" << p.name << ") "
                    << (p.reference ? fixed(*p.reference, 3) : std::string("-")) << " -> "
                    << (p.now ? fixed(*p.now, 3) : std::string("-")) << ' ' << p.unit << '\n';
        for (const model::MetricDrift &m : c.metrics)
            ctx.out << "  " << m.test << ' ' << model::driftMetricKey(m.metric) << ' '
                    << fixed(m.reference, 3) << " -> " << fixed(m.now, 3) << ' ' << m.unit
                    << "  change " << fixed(m.deltaPercent, 1) << " (limit "
                    << fixed(m.thresholdPercent, 1) << ")  " << (m.exceeded ? "EXCEEDED" : "ok")
                    << '\n';
        ctx.out << "restored: the set value after each test\n";
    }
    if (c.exceeded())
        return ctx.fail(kExitDeviceError, "a figure drifted beyond its limit");
    return kExitOk;
}

} // namespace

int runReference(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    ConfirmGate gate(ctx, args);
    int code = kExitOk;
    auto options = startCommand(args, ctx, kName, kSynopsis, &code);
    if (!options)
        return code;
    if (args.isEmpty())
        return failUsage(ctx, kName, "say what to do: save or compare");
    const QString what = args.takeFirst();
    if (what == QLatin1String("save"))
        return save(args, ctx, gate, *options);
    if (what == QLatin1String("compare"))
        return compare(args, ctx, gate, *options);
    return failUsage(ctx, kName, "the action is save or compare");
}

} // namespace vt::cli
