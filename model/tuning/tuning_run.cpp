#include "tuning_run.h"

#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/file_write.h"
#include "model/text_language.h"

#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <algorithm>
#include <map>

namespace vt::model {

namespace {

QString jsonPathFor(const QString &path)
{
    const QFileInfo info(path);
    return info.path() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".json");
}

QString csvPathFor(const QString &path)
{
    const QFileInfo info(path);
    return info.path() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".csv");
}

std::optional<QByteArray> readBounded(const QString &path, QString *why)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = QObject::tr("Cannot open %1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    if (file.size() > static_cast<qint64>(kMaxRunFileBytes)) {
        *why = QObject::tr("%1 is larger than 256 MiB.").arg(path);
        return std::nullopt;
    }
    return file.read(static_cast<qint64>(kMaxRunFileBytes));
}

} // namespace

std::unique_ptr<TuningRun> newRun(int number, const TestRunSetup &setup, const DeviceImage &image)
{
    auto run = std::make_unique<TuningRun>();
    run->number = number;
    run->started = QDateTime::currentDateTime();
    run->module = setup.module.address;
    run->family = setup.module.identification.family;
    run->mode = setup.module.identification.mode;
    run->dictionary = setup.module.dictionary;
    run->setValueRow = setup.setValueRow;
    run->responseRow = setup.actualRow;
    run->spec = setup.signal.spec();
    run->settings = settingsSnapshot(image, setup.module);
    return run;
}

std::vector<RunSetting> settingsSnapshot(const DeviceImage &image, const ModuleInfo &module)
{
    std::vector<RunSetting> out;
    if (!module.dictionary)
        return out;
    for (const dev::ParamMeta &row : module.dictionary->params) {
        if (row.kind != dev::RowKind::Setting || row.isString())
            continue;
        if (const auto value = image.value(module.address, &row))
            out.push_back({row.name, dev::rawNumber(*value)});
    }
    return out;
}

std::vector<SettingDifference> settingDifferences(const TuningRun &a, const TuningRun &b)
{
    std::map<std::string, double> inB;
    for (const RunSetting &s : b.settings)
        inB[s.name] = s.raw;
    std::vector<SettingDifference> out;
    for (const RunSetting &s : a.settings) {
        const auto it = inB.find(s.name);
        if (it == inB.end())
            out.push_back({s.name, s.raw, std::nullopt});
        else if (it->second != s.raw)
            out.push_back({s.name, s.raw, it->second});
        if (it != inB.end())
            inB.erase(it);
    }
    for (const RunSetting &s : b.settings)
        if (inB.count(s.name))
            out.push_back({s.name, std::nullopt, s.raw});
    return out;
}

QString runTitle(const TuningRun &run)
{
    const dev::ParamMeta *row = run.setValueRow;
    const QString unit = row ? QString::fromStdString(row->unit) : QString();
    const auto value = [&](double v) {
        return QLocale().toString(v, 'f', row ? row->scale.decimals : 3);
    };
    const SignalSpec &s = run.spec;
    QString what;
    switch (s.kind) {
    case SignalKind::Step:
        what = QObject::tr("step %1 → %2 %3").arg(value(s.from), value(s.to), unit);
        break;
    case SignalKind::Sweep:
        what = QObject::tr("sweep %1 … %2 Hz")
                   .arg(QLocale().toString(s.fromHz, 'g', 3), QLocale().toString(s.toHz, 'g', 3));
        break;
    default:
        what = QObject::tr("%1 %2 Hz ± %3 %4")
                   .arg(QString::fromLatin1(key(s.kind)), QLocale().toString(s.frequencyHz, 'g', 3),
                        value(s.amplitude), unit);
        break;
    }
    return QObject::tr("Run %1 · %2 · module %3 %4")
        .arg(run.number)
        .arg(what)
        .arg(run.module)
        .arg(row ? QString::fromStdString(row->name) : QString());
}

RunFileData runFileData(const TuningRun &run)
{
    RunFileData data;
    data.number = run.number;
    data.started = run.started.toString(Qt::ISODateWithMs).toStdString();
    data.module = run.module;
    data.family = run.family;
    data.mode = run.mode;
    data.setValue = run.setValueRow ? run.setValueRow->name : std::string();
    data.response = run.responseRow ? run.responseRow->name : std::string();
    data.spec = run.spec;
    data.end = key(run.end);
    data.restored = run.restored;
    data.writes = run.recording.writes;
    data.cycles = run.recording.cycles;
    data.setValueSamples = run.recording.setValue;
    for (const dev::ParamMeta *row : run.recording.rows)
        data.channelNames.push_back(row->name);
    data.channels = run.recording.channels;
    data.settings = run.settings;
    return data;
}

bool runFromData(const RunFileData &data, const dev::Dictionary &dictionary, TuningRun &run,
                 QString *why)
{
    run.dictionary = &dictionary;
    const auto signal = TestSignal::make(data.spec);
    run.setValueRow = dictionary.find(data.setValue);
    run.responseRow = data.response.empty() ? nullptr : dictionary.find(data.response);
    if (!signal || !run.setValueRow) {
        *why = QObject::tr("It names a signal or a set value that does not exist.");
        return false;
    }
    for (const std::string &name : data.channelNames) {
        const dev::ParamMeta *row = dictionary.find(name);
        if (!row) {
            *why = QObject::tr("It records %1, which %2 does not have.")
                       .arg(QString::fromStdString(name), QString::fromStdString(data.family));
            return false;
        }
        run.recording.rows.push_back(row);
    }
    run.number = data.number;
    run.started = QDateTime::fromString(QString::fromStdString(data.started), Qt::ISODateWithMs);
    run.module = data.module;
    run.family = data.family;
    run.mode = data.mode;
    run.spec = data.spec;
    run.recording.channels = data.channels;
    run.recording.setValue = data.setValueSamples;
    run.recording.writes = data.writes;
    run.recording.cycles = data.cycles;
    run.end = dev::fromKey<TestEnd>(data.end).value_or(TestEnd::Finished);
    run.restored = data.restored;
    run.settings = data.settings;
    run.analysis = analyseRun(*signal, run.recording, run.responseRow, run.setValueRow);
    return true;
}

QString saveRun(const TuningRun &run, const QString &csvPath)
{
    const RunFileData data = runFileData(run);
    if (QString e = writeFileAtomically(csvPathFor(csvPath), runCsv(data)); !e.isEmpty())
        return e;
    return writeFileAtomically(jsonPathFor(csvPath), runJson(data));
}

std::optional<TuningRun> loadRun(const QString &path, const dev::DictionarySet &dictionaries,
                                 QString *why)
{
    QString ignored;
    if (!why)
        why = &ignored;
    const auto json = readBounded(jsonPathFor(path), why);
    const auto csv = json ? readBounded(csvPathFor(path), why) : std::nullopt;
    if (!json || !csv)
        return std::nullopt;
    auto parsed =
        parseRunFiles(std::string_view(json->constData(), static_cast<std::size_t>(json->size())),
                      std::string_view(csv->constData(), static_cast<std::size_t>(csv->size())));
    if (!parsed.ok()) {
        *why = QObject::tr("%1 is not a readable run: %2")
                   .arg(path, QString::fromStdString(parsed.error()));
        return std::nullopt;
    }
    const RunFileData &data = *parsed;
    const dev::Dictionary *dictionary = dictionaries.find(data.family);
    if (!dictionary) {
        *why = QObject::tr("%1 is a run of %2, a family this ValveTune does not know.")
                   .arg(path, QString::fromStdString(data.family));
        return std::nullopt;
    }
    TuningRun run;
    QString bad;
    if (!runFromData(data, *dictionary, run, &bad)) {
        *why = QObject::tr("%1: %2").arg(path, bad);
        return std::nullopt;
    }
    return run;
}

} // namespace vt::model
