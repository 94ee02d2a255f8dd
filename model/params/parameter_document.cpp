#include "parameter_document.h"

#include "access/hart_universal_rows.h"
#include "dict/cooking.h"
#include "dict/identify.h"
#include "value_commands.h"

#include <QCoreApplication>
#include <algorithm>
#include <set>

namespace vt::model {
namespace {

// "opat 51.03, mode 3": the family, version and mode as one sentence of the language shown.
QString moduleIdentity(const dev::Dictionary &dict, const std::string &version,
                       const std::string &mode, dev::Language lang)
{
    const QString family = QString::fromStdString(dict.family);
    const QString v = QString::fromStdString(dev::versionText(version).in(lang));
    const QString m = QString::fromStdString(mode);
    if (mode.empty())
        return version.empty() ? family : QStringLiteral("%1 %2").arg(family, v);
    if (version.empty())
        return QCoreApplication::translate("vt::model::ParameterDocument", "%1, mode %2")
            .arg(family, m);
    return QCoreApplication::translate("vt::model::ParameterDocument", "%1 %2, mode %3")
        .arg(family, v, m);
}

std::string valueText(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    if (const auto *text = std::get_if<std::string>(&value))
        return "\"" + *text + "\"";
    return dev::formatValue(row, dev::rawNumber(value), lang);
}

} // namespace

ParameterDocument::ParameterDocument(QObject *parent) : QObject(parent)
{
    connect(&m_ownImage, &DeviceImage::changed, this, &ParameterDocument::onImageChanged);
    connect(&m_ownImage, &DeviceImage::currencyChanged, this,
            &ParameterDocument::onCurrencyChanged);
}

ParameterDocument::~ParameterDocument() = default;

int ParameterDocument::findModule(int address) const
{
    for (std::size_t i = 0; i < m_modules.size(); ++i)
        if (m_modules[i].address == address)
            return static_cast<int>(i);
    return -1;
}

void ParameterDocument::setLanguage(dev::Language language)
{
    if (language == m_language)
        return;
    m_language = language;
    // The undo steps say what they did in the new language. QUndoStack hands out its steps as
    // const only; their text is all that changes here.
    for (int i = 0; i < m_undo.count(); ++i)
        if (auto *step = dynamic_cast<const SetValuesCommand *>(m_undo.command(i)))
            const_cast<SetValuesCommand *>(step)->retranslate();
    for (std::size_t i = 0; i < m_modules.size(); ++i) {
        ParamModule &m = m_modules[i];
        if (m.identityOwn && m.dictionary) {
            m.identity = moduleIdentity(*m.dictionary, m.version, m.mode, m_language);
            emit moduleChanged(static_cast<int>(i));
        } else if (!m.identityDevice.en.empty()) {
            m.identity = QString::fromStdString(m.identityDevice.in(m_language));
            emit moduleChanged(static_cast<int>(i));
        }
    }
    emit languageChanged();
}

void ParameterDocument::resetModules(std::vector<ParamModule> modules)
{
    m_modules = std::move(modules);
    emit modulesReset();
}

void ParameterDocument::clear()
{
    m_undo.clear();
    m_unmapped.clear();
    m_fileHeader = {};
    m_filePath.clear();
    resetModules({});
    emit filePathChanged(m_filePath);
}

void ParameterDocument::createNew(const NewFileChoice &choice,
                                  const dev::DictionarySet &dictionaries)
{
    loadFile(newParamFile(choice, {}, std::chrono::system_clock::now()), dictionaries, QString());
}

void ParameterDocument::setDeviceImage(DeviceImage *image)
{
    DeviceImage *now = image ? image : &m_ownImage;
    if (now == &deviceImage())
        return;
    if (m_image)
        m_image->disconnect(this);
    m_ownImage.disconnect(this);
    m_image = image;
    connect(now, &DeviceImage::changed, this, &ParameterDocument::onImageChanged);
    connect(now, &DeviceImage::currencyChanged, this, &ParameterDocument::onCurrencyChanged);
    for (ParamModule &m : m_modules)
        m.paired = m.online;
    onCurrencyChanged();
}

QStringList ParameterDocument::attachDevice(const std::vector<ModuleInfo> &infos, bool addMissing)
{
    QStringList report;
    std::vector<ParamModule> modules = m_modules;
    auto sameFamily = [](const ParamModule &m, const ModuleInfo &info) {
        return m.dictionary == info.dictionary;
    };
    auto family = [](const dev::Dictionary *d) {
        return d ? QString::fromStdString(d->family) : tr("unknown");
    };
    // A one-module document goes onto the one module of its family on the node, whatever its
    // address.
    if (modules.size() == 1 && infos.size() == 1 && !modules[0].online &&
        sameFamily(modules[0], infos[0]) && modules[0].address != infos[0].address) {
        report << tr("Module %1 of the document goes to module %2 of the node.")
                      .arg(modules[0].address)
                      .arg(infos[0].address);
        modules[0].address = infos[0].address;
    }
    std::vector<bool> pairedNow(modules.size(), false);
    for (const ModuleInfo &info : infos) {
        if (!info.dictionary)
            continue;
        auto it = std::find_if(modules.begin(), modules.end(), [&](const ParamModule &m) {
            return m.address == info.address && sameFamily(m, info);
        });
        if (it == modules.end()) {
            if (!addMissing) {
                report << tr("Module %1 of the node (%2) is not in the document: not shown.")
                              .arg(info.address)
                              .arg(family(info.dictionary));
                continue;
            }
            modules.push_back(ParamModule{});
            pairedNow.push_back(false);
            it = std::prev(modules.end());
            it->address = info.address;
            it->dictionary = info.dictionary;
        } else if (!addMissing && (it->version != info.identification.version ||
                                   it->mode != info.identification.mode)) {
            report << tr("Module %1: the document is for %2, the device is %3. Rows the device "
                         "does not apply are kept but not written.")
                          .arg(info.address)
                          .arg(it->identity,
                               moduleIdentity(*info.dictionary, info.identification.version,
                                              info.identification.mode, m_language));
        }
        pairedNow[static_cast<std::size_t>(it - modules.begin())] = true;
        it->online = true;
        it->paired = true;
        it->version = info.identification.version;
        it->mode = info.identification.mode;
        it->versRaw = info.versRaw;
        it->identityDevice = info.identityText;
        it->identityOwn = info.identityText.en.empty();
        it->identity = it->identityOwn
                           ? moduleIdentity(*info.dictionary, it->version, it->mode, m_language)
                           : QString::fromStdString(info.identityText.in(m_language));
    }
    for (std::size_t i = 0; i < modules.size(); ++i) {
        if (pairedNow[i])
            continue;
        const ParamModule &m = modules[i];
        const auto other = std::find_if(infos.begin(), infos.end(), [&](const ModuleInfo &info) {
            return info.address == m.address;
        });
        if (other != infos.end())
            report << tr("Module %1 of the document is %2, the node's module %1 is %3: not "
                         "paired, it stays offline.")
                          .arg(m.address)
                          .arg(family(m.dictionary), family(other->dictionary));
        else
            report << tr("Module %1 of the document has no module on the node: it stays offline.")
                          .arg(m.address);
    }
    resetModules(std::move(modules));
    return report;
}

void ParameterDocument::detachDevice()
{
    for (std::size_t i = 0; i < m_modules.size(); ++i) {
        if (m_modules[i].online) {
            m_modules[i].online = false;
            emit moduleChanged(static_cast<int>(i));
            emit moduleValuesChanged(static_cast<int>(i));
        }
    }
}

void ParameterDocument::onImageChanged(int address, const std::vector<ImageChange> &changes)
{
    for (std::size_t i = 0; i < m_modules.size(); ++i) {
        ParamModule &m = m_modules[i];
        if (!m.online || m.address != address || !m.dictionary)
            continue;
        const auto &params = m.dictionary->params;
        std::vector<const dev::ParamMeta *> touched;
        for (const ImageChange &c : changes) {
            if (!c.row || params.empty() || c.row < &params.front() || c.row > &params.back())
                continue; // a row of another module's dictionary at this address
            touched.push_back(c.row);
            const auto working = m.value(c.row, Layer::Working);
            const bool follows = !c.row->writable() || !dev::files::isFileRow(*c.row) || !working ||
                                 (!m.file.count(c.row) && sameValue(working, c.before));
            if (follows)
                if (const auto now = deviceImage().value(address, c.row))
                    m.working[c.row] = *now;
        }
        const int index = static_cast<int>(i);
        if (touched.size() > 16) {
            emit moduleValuesChanged(index);
        } else {
            for (const dev::ParamMeta *row : touched)
                emit valueChanged(index, row);
        }
    }
}

void ParameterDocument::onCurrencyChanged()
{
    for (std::size_t i = 0; i < m_modules.size(); ++i)
        if (m_modules[i].paired)
            emit moduleValuesChanged(static_cast<int>(i));
}

void ParameterDocument::loadFile(const dev::files::ParamFile &file,
                                 const dev::DictionarySet &dictionaries, const QString &path)
{
    std::vector<ParamModule> modules;
    m_unmapped.clear();
    for (const dev::files::ModuleRecord &record : file.modules) {
        const dev::Dictionary *dict = dictionaries.find(record.family);
        if (!dict) {
            m_unmapped.push_back(record);
            continue;
        }
        ParamModule m;
        m.address = record.address;
        m.dictionary = dict;
        m.version = record.version;
        m.mode = record.mode;
        m.label = QString::fromStdString(record.label);
        m.identity = moduleIdentity(*dict, record.version, record.mode, m_language);
        m.identityOwn = true;
        m.record = record;
        m.mapReport = dev::files::mapModule(record, *dict);
        for (const dev::files::RowMapping &r : m.mapReport->rows) {
            // Process and live values in an old file are not settings: neither shown as the
            // document's value nor written (the map report names them).
            if (r.applies() && r.meta && r.row != dev::files::RowMapping::kNoRow &&
                dev::files::isFileRow(*r.meta)) {
                m.file[r.meta] = record.values[r.row].raw;
                m.working[r.meta] = record.values[r.row].raw;
            }
        }
        modules.push_back(std::move(m));
    }
    m_fileHeader = file;
    m_fileHeader.modules.clear();
    m_undo.clear();
    m_filePath = path;
    resetModules(std::move(modules));
    emit filePathChanged(m_filePath);
}

dev::files::ParamFile ParameterDocument::toParamFile(const std::string &tool) const
{
    dev::files::ParamFile file = m_fileHeader;
    file.tool = tool;
    if (file.created.empty())
        file.created = dev::files::isoUtc(std::chrono::system_clock::now());
    for (const ParamModule &m : m_modules) {
        dev::files::ModuleRecord record = m.record.value_or(dev::files::ModuleRecord{});
        record.address = m.address;
        record.family = m.dictionary->family;
        record.version = m.version;
        record.mode = m.mode;
        record.label = m.label.toStdString();
        std::set<const dev::ParamMeta *> written;
        // A file holds settings only: process and live values an old file had are dropped.
        std::erase_if(record.values, [&](const dev::files::ValueRow &row) {
            bool byAddress = false;
            const dev::ParamMeta *meta = dev::files::findMeta(*m.dictionary, row, &byAddress);
            return meta && !dev::files::isFileRow(*meta);
        });
        for (dev::files::ValueRow &row : record.values) {
            bool byAddress = false;
            const dev::ParamMeta *meta = dev::files::findMeta(*m.dictionary, row, &byAddress);
            const auto it = meta ? m.working.find(meta) : m.working.end();
            if (it == m.working.end())
                continue; // not applied here: written back as it was read
            dev::files::ValueRow fresh = dev::files::makeValueRow(*meta, it->second);
            fresh.extra = row.extra;
            row = std::move(fresh);
            written.insert(meta);
        }
        for (const dev::ParamMeta &meta : m.dictionary->params) {
            const auto it = m.working.find(&meta);
            if (it != m.working.end() && !written.count(&meta) &&
                meta.access != dev::Access::Write && dev::files::isFileRow(meta))
                record.values.push_back(dev::files::makeValueRow(meta, it->second));
        }
        file.modules.push_back(std::move(record));
    }
    for (const dev::files::ModuleRecord &record : m_unmapped)
        file.modules.push_back(record);
    std::sort(file.modules.begin(), file.modules.end(),
              [](const auto &a, const auto &b) { return a.address < b.address; });
    // Two modules of one address (a file module of another family beside the device's) cannot
    // both be saved under that address: the later keeps its values under the next free one.
    for (std::size_t i = 1; i < file.modules.size(); ++i)
        if (file.modules[i].address <= file.modules[i - 1].address)
            file.modules[i].address = file.modules[i - 1].address + 1;
    return file;
}

void ParameterDocument::markSaved(const QString &path)
{
    const dev::files::ParamFile saved = toParamFile({});
    for (ParamModule &m : m_modules) {
        m.file = m.working;
        for (const dev::files::ModuleRecord &record : saved.modules)
            if (record.family == m.dictionary->family && record.address == m.address)
                m.record = record;
    }
    m_fileHeader = saved;
    m_fileHeader.modules.clear();
    m_undo.setClean();
    if (path != m_filePath) {
        m_filePath = path;
        emit filePathChanged(m_filePath);
    }
    for (int i = 0; i < moduleCount(); ++i)
        emit moduleValuesChanged(i);
}

std::optional<dev::RawValue> ParameterDocument::value(int module, const dev::ParamMeta *row,
                                                      Layer layer) const
{
    if (module < 0 || module >= moduleCount())
        return std::nullopt;
    const ParamModule &m = m_modules[static_cast<std::size_t>(module)];
    if (layer == Layer::Device)
        return m.paired ? deviceImage().value(m.address, row) : std::nullopt;
    return m.value(row, layer);
}

bool ParameterDocument::deviceCurrent(int module, const dev::ParamMeta *row) const
{
    if (module < 0 || module >= moduleCount())
        return false;
    const ParamModule &m = m_modules[static_cast<std::size_t>(module)];
    return m.online && deviceImage().currentValue(m.address, row).has_value();
}

std::vector<const dev::ParamMeta *> ParameterDocument::rowsToRead(int module) const
{
    std::vector<const dev::ParamMeta *> rows;
    if (module < 0 || module >= moduleCount() || !this->module(module).online)
        return rows;
    const ParamModule &m = this->module(module);
    for (const dev::ParamMeta &row : m.dictionary->params)
        if (row.readable() && row.writable() && dev::files::isFileRow(row) && m.active(row) &&
            m.working.count(&row) && !deviceCurrent(module, &row))
            rows.push_back(&row);
    return rows;
}

std::optional<QString> ParameterDocument::edit(int module, const dev::ParamMeta *row,
                                               const dev::RawValue &value)
{
    if (module < 0 || module >= moduleCount() || !row)
        return tr("No such parameter.");
    const QString name = QString::fromStdString(row->name);
    if (!row->writable())
        return tr("%1 is read only.").arg(name);
    if (row->isString() != dev::isText(value))
        return row->isString() ? tr("%1 takes a text.").arg(name)
                               : tr("%1 takes a number.").arg(name);
    if (const auto *text = std::get_if<std::string>(&value)) {
        const int characters = dev::access::textCapacity(*row);
        if (characters > 0 && text->size() > static_cast<std::size_t>(characters))
            return tr("%1 takes at most %n character(s).", nullptr, characters).arg(name);
    } else if (auto error = dev::checkRange(*row, dev::rawNumber(value))) {
        return QString::fromStdString(error->message.in(m_language));
    }
    const auto before = this->value(module, row);
    if (sameValue(before, value))
        return std::nullopt;
    // The module is named: a node has the same parameter on every module.
    const UndoText text = [this, address = m_modules[static_cast<std::size_t>(module)].address, row,
                           value] {
        return tr("module %1 %2 = %3")
            .arg(address)
            .arg(QString::fromStdString(row->name),
                 QString::fromStdString(valueText(*row, value, m_language)));
    };
    m_undo.push(new SetValuesCommand(*this, {{module, row, before, value}}, text));
    return std::nullopt;
}

void ParameterDocument::editMany(const std::vector<Change> &changes, UndoText undoText)
{
    std::vector<SetValuesCommand::Row> rows;
    for (const Change &c : changes) {
        const auto before = value(c.module, c.row);
        if (!sameValue(before, c.value))
            rows.push_back({c.module, c.row, before, c.value});
    }
    if (!rows.empty())
        m_undo.push(new SetValuesCommand(*this, std::move(rows), std::move(undoText)));
}

void ParameterDocument::editNumbers(
    int module, const std::vector<std::pair<const dev::ParamMeta *, double>> &values,
    UndoText undoText)
{
    std::vector<Change> changes;
    for (const auto &[row, number] : values)
        changes.push_back({module, row, dev::RawValue{number}});
    editMany(changes, std::move(undoText));
}

void ParameterDocument::setWorking(int module, const dev::ParamMeta *row,
                                   const std::optional<dev::RawValue> &value)
{
    if (module < 0 || module >= moduleCount() || !row)
        return;
    auto &working = m_modules[static_cast<std::size_t>(module)].working;
    if (value)
        working[row] = *value;
    else
        working.erase(row);
    emit valueChanged(module, row);
}

std::vector<WriteItem> ParameterDocument::pendingWrites(int module) const
{
    std::vector<WriteItem> items;
    if (module < 0 || module >= moduleCount())
        return items;
    const ParamModule &m = m_modules[static_cast<std::size_t>(module)];
    for (const dev::ParamMeta &row : m.dictionary->params) {
        if (!row.writable() || !m.active(row) || !dev::files::isFileRow(row))
            continue;
        const auto working = m.value(&row, Layer::Working);
        const auto device =
            deviceCurrent(module, &row) ? value(module, &row, Layer::Device) : std::nullopt;
        if (!working || sameValue(working, device))
            continue;
        WriteItem item;
        item.row = &row;
        item.value = *working;
        item.before = device;
        items.push_back(std::move(item));
    }
    return items;
}

bool ParameterDocument::differsFromDevice(int module, const dev::ParamMeta *row) const
{
    if (!row || !dev::files::isFileRow(*row))
        return false;
    const auto device = value(module, row, Layer::Device);
    return device && !sameValue(value(module, row), device);
}

bool ParameterDocument::changed(int module, const dev::ParamMeta *row) const
{
    if (!row || !row->writable() || !dev::files::isFileRow(*row))
        return false;
    const auto working = value(module, row);
    if (!working)
        return false;
    if (const auto file = value(module, row, Layer::File))
        return !sameValue(working, file);
    if (const auto device = value(module, row, Layer::Device))
        return !sameValue(working, device);
    if (row->defaultValue && !row->isString())
        return !sameValue(working, dev::RawValue{*row->defaultValue});
    return false;
}

void ParameterDocument::revertToDevice()
{
    std::vector<Change> changes;
    for (int i = 0; i < moduleCount(); ++i)
        for (const dev::ParamMeta &row : m_modules[static_cast<std::size_t>(i)].dictionary->params)
            if (row.writable() && dev::files::isFileRow(row))
                if (const auto device = value(i, &row, Layer::Device))
                    changes.push_back({i, &row, *device});
    editMany(changes, [] { return tr("Revert to device"); });
}

void ParameterDocument::revertToFile()
{
    std::vector<Change> changes;
    for (int i = 0; i < moduleCount(); ++i)
        for (const auto &[row, value] : m_modules[static_cast<std::size_t>(i)].file)
            if (row->writable())
                changes.push_back({i, row, value});
    editMany(changes, [] { return tr("Revert to file"); });
}

} // namespace vt::model
