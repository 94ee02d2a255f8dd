#include "reference_fingerprint.h"

#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/file_write.h"
#include "model/tuning/workbench_rows.h"

#include <QDateTime>
#include <QFile>
#include <QObject>
#include <cmath>
#include <limits>

namespace vt::model {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The first up and the first down edge of a run, with their analysis.
const StepResult *edgeOf(const TuningRun &run, bool up)
{
    for (const StepResult &s : run.analysis.steps)
        if ((s.edge.to > s.edge.from) == up)
            return &s;
    return nullptr;
}

// Each test's figures as the comparison reads them, against nothing: the reference's own.
std::vector<ReferenceFigure> figuresOf(const std::vector<ReferenceTestSpec> &tests,
                                       const std::vector<std::shared_ptr<TuningRun>> &runs,
                                       const std::string &unit)
{
    std::vector<ReferenceFigure> out;
    const DriftThresholds any;
    for (std::size_t i = 0; i < tests.size() && i < runs.size(); ++i) {
        const TuningRun &run = *runs[i];
        std::vector<std::pair<std::string, std::vector<MetricDrift>>> parts;
        if (tests[i].spec.kind == SignalKind::Sweep) {
            parts.emplace_back("sweep", sweepDrift(run.analysis.f3dB.value_or(kNaN), kNaN,
                                                   run.analysis.f90deg.value_or(kNaN), kNaN, any));
        } else {
            for (const bool up : {true, false}) {
                const StepResult *s = edgeOf(run, up);
                parts.emplace_back(
                    up ? "step-up" : "step-down",
                    stepDrift(s ? s->metrics : std::nullopt, std::nullopt, any, unit));
            }
        }
        for (const auto &[test, drifts] : parts)
            for (const MetricDrift &d : drifts)
                out.push_back({test, std::string(driftMetricKey(d.metric)), d.reference, d.unit});
    }
    return out;
}

} // namespace

std::vector<ReferenceTestSpec> referenceTests(const ReferencePlan &plan)
{
    std::vector<ReferenceTestSpec> out;
    SignalSpec steps;
    steps.kind = SignalKind::Step;
    steps.from = plan.centre - plan.amplitude;
    steps.to = plan.centre + plan.amplitude;
    steps.hold = plan.hold;
    steps.repeats = 1;
    steps.direction = StepDirection::Both;
    out.push_back({"steps", steps});
    if (plan.sweep) {
        SignalSpec sweep;
        sweep.kind = SignalKind::Sweep;
        sweep.amplitude = plan.amplitude;
        sweep.offset = plan.centre;
        sweep.fromHz = plan.fromHz;
        sweep.toHz = plan.toHz;
        sweep.pointsPerDecade = plan.pointsPerDecade;
        out.push_back({"sweep", sweep});
    }
    return out;
}

std::vector<ReferenceTestSpec> Reference::tests() const
{
    std::vector<ReferenceTestSpec> out;
    for (const ReferenceTest &t : file.tests)
        out.push_back({t.key, t.run.spec});
    return out;
}

Reference makeReference(const ModuleInfo &module, const dev::ParamMeta &setValue,
                        const ReferencePlan &plan, const std::vector<RunSetting> &settings,
                        std::vector<std::shared_ptr<TuningRun>> runs, dev::Language language)
{
    Reference r;
    ReferenceFileData &f = r.file;
    f.saved = QDateTime::currentDateTime().toString(Qt::ISODateWithMs).toStdString();
    f.family = module.identification.family;
    f.version = module.identification.version;
    f.mode = module.identification.mode;
    f.address = module.address;
    f.setValue = setValue.name;
    f.centre = plan.centre;
    f.amplitude = plan.amplitude;
    for (const RunSetting &s : settings) {
        const dev::ParamMeta *row = module.dictionary ? module.dictionary->find(s.name) : nullptr;
        f.settings.push_back(
            {s.name, s.raw, row ? dev::formatNumber(*row, s.raw, language) : std::to_string(s.raw),
             row ? row->unit : std::string()});
        if (row && !row->enums.empty())
            f.settings.back().display = dev::formatValue(*row, s.raw, language);
    }
    const std::vector<ReferenceTestSpec> tests = referenceTests(plan);
    for (std::size_t i = 0; i < tests.size() && i < runs.size(); ++i)
        f.tests.push_back({tests[i].key, runFileData(*runs[i])});
    f.figures = figuresOf(tests, runs, setValue.unit);
    r.runs = std::move(runs);
    return r;
}

QString saveReference(const Reference &reference, const QString &path)
{
    return writeFileAtomically(path, referenceJson(reference.file));
}

std::optional<Reference> loadReference(const QString &path, const dev::DictionarySet &dictionaries,
                                       QString *why)
{
    QString ignored;
    if (!why)
        why = &ignored;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = QObject::tr("Cannot open %1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    if (file.size() > static_cast<qint64>(kMaxReferenceFileBytes)) {
        *why = QObject::tr("%1 is larger than 256 MiB.").arg(path);
        return std::nullopt;
    }
    const QByteArray bytes = file.read(static_cast<qint64>(kMaxReferenceFileBytes));
    auto parsed = parseReferenceFile(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (!parsed.ok()) {
        *why = QObject::tr("%1 is not a readable reference: %2")
                   .arg(path, QString::fromStdString(parsed.error()));
        return std::nullopt;
    }
    Reference r;
    r.file = std::move(parsed).value();
    const dev::Dictionary *dictionary = dictionaries.find(r.file.family);
    if (!dictionary) {
        *why = QObject::tr("%1 is a reference of %2, a family this ValveTune does not know.")
                   .arg(path, QString::fromStdString(r.file.family));
        return std::nullopt;
    }
    for (const ReferenceTest &t : r.file.tests) {
        auto run = std::make_shared<TuningRun>();
        QString bad;
        if (!runFromData(t.run, *dictionary, *run, &bad)) {
            *why = QObject::tr("%1: test %2: %3").arg(path, QString::fromStdString(t.key), bad);
            return std::nullopt;
        }
        r.runs.push_back(std::move(run));
    }
    return r;
}

QString referenceFitProblem(const ReferenceFileData &reference, const ModuleInfo &module)
{
    const std::string &family = module.identification.family;
    if (reference.family != family)
        return QObject::tr("The reference was taken on a %1 module; module %2 is a %3.")
            .arg(QString::fromStdString(reference.family))
            .arg(module.address)
            .arg(QString::fromStdString(family));
    if (reference.mode != module.identification.mode)
        return QObject::tr("The reference was taken in mode %1; module %2 runs in mode %3: its "
                           "set values and responses are other rows.")
            .arg(QString::fromStdString(reference.mode))
            .arg(module.address)
            .arg(QString::fromStdString(module.identification.mode));
    bool tested = false;
    if (module.dictionary)
        for (const dev::ParamMeta *row :
             testSetValueRows(*module.dictionary, module.identification.mode))
            tested = tested || row->name == reference.setValue;
    if (!tested)
        return QObject::tr("Module %1 has no set value %2 a test can drive.")
            .arg(module.address)
            .arg(QString::fromStdString(reference.setValue));
    return {};
}

QStringList referenceNotes(const ReferenceFileData &reference, const ModuleInfo &module)
{
    QStringList notes;
    if (reference.version != module.identification.version)
        notes << QObject::tr("The reference was taken with software %1; the module has %2.")
                     .arg(QString::fromStdString(reference.version),
                          QString::fromStdString(module.identification.version));
    if (reference.address != module.address)
        notes << QObject::tr("The reference was taken at address %1; this module is at %2.")
                     .arg(reference.address)
                     .arg(module.address);
    return notes;
}

ReferenceComparison compareWithReference(const Reference &reference,
                                         const std::vector<std::shared_ptr<TuningRun>> &now,
                                         const std::vector<RunSetting> &settings,
                                         const DriftThresholds &thresholds, dev::Language language)
{
    ReferenceComparison c;
    const int module = reference.file.address;
    std::vector<RunSetting> was;
    for (const ReferenceSetting &s : reference.file.settings)
        was.push_back({s.name, s.raw});
    const dev::Dictionary *dictionary =
        reference.runs.empty() ? nullptr : reference.runs.front()->dictionary;
    if (dictionary)
        c.params = paramDrift(module, *dictionary, was, settings, language);
    const auto tag = [&](std::vector<MetricDrift> drifts, const std::string &test) {
        for (MetricDrift &d : drifts) {
            d.module = module;
            d.test = test;
            c.metrics.push_back(std::move(d));
        }
    };
    for (std::size_t i = 0; i < reference.runs.size(); ++i) {
        const TuningRun &ref = *reference.runs[i];
        const TuningRun *cur = i < now.size() ? now[i].get() : nullptr;
        if (ref.spec.kind == SignalKind::Sweep) {
            const auto f = [](const TuningRun *r, const std::optional<double> RunAnalysis::*m) {
                return r && (r->analysis.*m) ? *(r->analysis.*m) : kNaN;
            };
            tag(sweepDrift(f(&ref, &RunAnalysis::f3dB), f(cur, &RunAnalysis::f3dB),
                           f(&ref, &RunAnalysis::f90deg), f(cur, &RunAnalysis::f90deg), thresholds),
                "sweep");
            if (cur) {
                DriftOverlay o;
                o.test = "sweep";
                o.frequency = true;
                for (const FrequencyPoint &p : ref.analysis.points) {
                    if (!p.valid)
                        continue;
                    for (const FrequencyPoint &q : cur->analysis.points)
                        if (q.valid &&
                            std::abs(q.frequencyHz - p.frequencyHz) < 1e-9 * p.frequencyHz) {
                            o.x.push_back(p.frequencyHz);
                            o.reference.push_back(p.gainDb);
                            o.now.push_back(q.gainDb);
                        }
                }
                c.overlays.push_back(std::move(o));
            }
            continue;
        }
        const std::string unit = ref.setValueRow ? ref.setValueRow->unit : std::string();
        for (const bool up : {true, false}) {
            const std::string test = up ? "step-up" : "step-down";
            const StepResult *a = edgeOf(ref, up);
            const StepResult *b = cur ? edgeOf(*cur, up) : nullptr;
            tag(stepDrift(a ? a->metrics : std::nullopt, b ? b->metrics : std::nullopt, thresholds,
                          unit),
                test);
            const Samples *x = ref.recording.channel(ref.responseRow);
            const Samples *y = cur ? cur->recording.channel(cur->responseRow) : nullptr;
            if (a && b && x && y)
                c.overlays.push_back(stepOverlay(test, *x, a->edge, *y, b->edge));
        }
    }
    return c;
}

} // namespace vt::model
