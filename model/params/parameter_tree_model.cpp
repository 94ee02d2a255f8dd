#include "parameter_tree_model.h"

#include "block_titles.h"
#include "dict/cooking.h"
#include "dsp408/state_machine.h"
#include "model/number_text.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QGuiApplication>
#include <QPalette>

namespace vt::model {
namespace {

QString qs(const std::string &s)
{
    return QString::fromStdString(s);
}

// A refusal that names its row as it is; one that does not gets the row's name in front.
QString naming(const dev::ParamMeta &row, const QString &refusal)
{
    const QString name = qs(row.name);
    return refusal.startsWith(name) ? refusal : ParameterTreeModel::tr("%1: %2").arg(name, refusal);
}

bool isBitField(const dev::ParamMeta &row)
{
    return !row.bits.empty() && row.enums.empty();
}

// A row the module updates at run time (the editor polls it while connected).
bool isLive(const ParamModule &m, const dev::ParamMeta &row)
{
    return row.kind == dev::RowKind::Live && m.active(row);
}

} // namespace

QString formatRaw(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    if (const auto *text = std::get_if<std::string>(&value))
        return qs(*text);
    const double raw = dev::rawNumber(value);
    if (isBitField(row)) {
        const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(raw));
        const QString hex = QStringLiteral("0x") +
                            QStringLiteral("%1").arg(bits, 4, 16, QLatin1Char('0')).toUpper();
        const std::string labels = dev::formatBits(row, bits, lang);
        return labels.empty() ? hex : hex + QStringLiteral(" (") + qs(labels) + QLatin1Char(')');
    }
    return qs(dev::formatValue(row, raw, lang));
}

QString stateWordText(const ParameterDocument &document, int moduleIndex)
{
    const ParamModule &module = document.module(moduleIndex);
    const dev::Language lang = document.language();
    if (!module.dictionary)
        return {};
    for (const dev::ParamMeta &row : module.dictionary->params) {
        if (!isBitField(row) || (row.block != "d" && row.block != "db") || !row.readable())
            continue;
        const auto value = document.value(moduleIndex, &row, Layer::Device);
        if (!value)
            return {};
        const QString word = qs(row.name) + QStringLiteral(" = ") + formatRaw(row, *value, lang);
        // ED1/SD1 manual and HART-7 manual §4.2.2: the device state the bits R M H D report.
        if (!module.dictionary->stateControlWord())
            return word;
        const auto state = dev::dsp408::stateOfStatusWord(
            static_cast<std::uint16_t>(static_cast<std::int64_t>(dev::rawNumber(*value))));
        if (!state)
            return word;
        return ParameterTreeModel::tr("%1: %2 (%3)")
            .arg(QString::fromLatin1(dev::dsp408::stateName(*state)),
                 qs(dev::dsp408::stateText(*state).in(lang)), word);
    }
    return {};
}

ParameterTreeModel::ParameterTreeModel(ParameterDocument &document, QObject *parent)
    : QAbstractItemModel(parent), m_document(document)
{
    rebuild();
    connect(&m_document, &ParameterDocument::modulesReset, this, [this] {
        beginResetModel();
        rebuild();
        endResetModel();
    });
    connect(&m_document, &ParameterDocument::moduleChanged, this, [this](int module) {
        const QModelIndex first = moduleIndex(module);
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
    });
    connect(&m_document, &ParameterDocument::valueChanged, this, &ParameterTreeModel::refreshRow);
    connect(&m_document, &ParameterDocument::moduleValuesChanged, this,
            &ParameterTreeModel::refreshModule);
    connect(&m_document, &ParameterDocument::languageChanged, this, [this] {
        refreshAll();
        emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    });
}

ParameterTreeModel::~ParameterTreeModel() = default;

void ParameterTreeModel::rebuild()
{
    m_nodes.clear();
    m_modules.clear();
    m_rowNode.clear();
    auto add = [this](Node node, int parent) {
        node.parent = parent;
        const int index = static_cast<int>(m_nodes.size());
        if (parent >= 0) {
            node.row = static_cast<int>(m_nodes[static_cast<std::size_t>(parent)].children.size());
            m_nodes[static_cast<std::size_t>(parent)].children.push_back(index);
        }
        m_nodes.push_back(std::move(node));
        return index;
    };
    for (int m = 0; m < m_document.moduleCount(); ++m) {
        const ParamModule &module = m_document.module(m);
        Node moduleNode;
        moduleNode.kind = NodeKind::Module;
        moduleNode.module = m;
        moduleNode.row = m;
        const int moduleIndex = add(moduleNode, -1);
        m_modules.push_back(moduleIndex);
        for (const std::string &block : blockOrder(*module.dictionary)) {
            Node blockNode;
            blockNode.kind = NodeKind::Block;
            blockNode.module = m;
            blockNode.block = block;
            const int blockIndex = add(blockNode, moduleIndex);
            std::map<int, int> branches;
            for (const dev::ParamMeta &row : module.dictionary->params) {
                if (row.block != block)
                    continue;
                int parent = blockIndex;
                if (row.branch > 0) {
                    auto it = branches.find(row.branch);
                    if (it == branches.end()) {
                        Node branchNode;
                        branchNode.kind = NodeKind::Branch;
                        branchNode.module = m;
                        branchNode.block = block;
                        branchNode.branch = row.branch;
                        it = branches.emplace(row.branch, add(branchNode, blockIndex)).first;
                    }
                    parent = it->second;
                }
                Node param;
                param.kind = NodeKind::Parameter;
                param.module = m;
                param.block = block;
                param.branch = row.branch;
                param.meta = &row;
                m_rowNode[{m, &row}] = add(param, parent);
            }
        }
    }
}

const ParameterTreeModel::Node *ParameterTreeModel::nodeAt(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return nullptr;
    const auto id = static_cast<std::size_t>(index.internalId());
    return id < m_nodes.size() ? &m_nodes[id] : nullptr;
}

QModelIndex ParameterTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid()) {
        if (row >= static_cast<int>(m_modules.size()))
            return {};
        return createIndex(row, column,
                           static_cast<quintptr>(m_modules[static_cast<std::size_t>(row)]));
    }
    const Node *p = nodeAt(parent);
    if (!p || parent.column() != 0 || row >= static_cast<int>(p->children.size()))
        return {};
    return createIndex(row, column,
                       static_cast<quintptr>(p->children[static_cast<std::size_t>(row)]));
}

QModelIndex ParameterTreeModel::parent(const QModelIndex &child) const
{
    const Node *node = nodeAt(child);
    if (!node || node->parent < 0)
        return {};
    const Node &p = m_nodes[static_cast<std::size_t>(node->parent)];
    return createIndex(p.row, 0, static_cast<quintptr>(node->parent));
}

int ParameterTreeModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return static_cast<int>(m_modules.size());
    if (parent.column() != 0)
        return 0;
    const Node *node = nodeAt(parent);
    return node ? static_cast<int>(node->children.size()) : 0;
}

int ParameterTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QModelIndex ParameterTreeModel::moduleIndex(int module) const
{
    if (module < 0 || module >= static_cast<int>(m_modules.size()))
        return {};
    return createIndex(module, 0,
                       static_cast<quintptr>(m_modules[static_cast<std::size_t>(module)]));
}

QModelIndex ParameterTreeModel::indexOf(int module, const dev::ParamMeta *row, int column) const
{
    const auto it = m_rowNode.find({module, row});
    if (it == m_rowNode.end())
        return {};
    return createIndex(m_nodes[static_cast<std::size_t>(it->second)].row, column,
                       static_cast<quintptr>(it->second));
}

const dev::ParamMeta *ParameterTreeModel::metaAt(const QModelIndex &index) const
{
    const Node *node = nodeAt(index);
    return node ? node->meta : nullptr;
}

int ParameterTreeModel::moduleAt(const QModelIndex &index) const
{
    const Node *node = nodeAt(index);
    return node ? node->module : -1;
}

QVariant ParameterTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case ColName: return tr("Name");
    case ColLabel: return tr("Parameter");
    case ColValue: return tr("Value");
    case ColDevice: return tr("Device");
    case ColFile: return tr("File");
    case ColRange: return tr("Range");
    case ColAccess: return tr("Access");
    default: return {};
    }
}

Qt::ItemFlags ParameterTreeModel::flags(const QModelIndex &index) const
{
    const Node *node = nodeAt(index);
    if (!node)
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (node->kind == NodeKind::Parameter && index.column() == ColValue && node->meta->writable() &&
        m_document.module(node->module).active(*node->meta))
        f |= Qt::ItemIsEditable;
    return f;
}

QString ParameterTreeModel::valueText(int module, const dev::ParamMeta &row, Layer layer) const
{
    const auto value = m_document.value(module, &row, layer);
    return value ? formatRaw(row, *value, m_document.language()) : QString();
}

QString ParameterTreeModel::deviceAgeText(int module, const dev::ParamMeta &row) const
{
    const ParamModule &m = m_document.module(module);
    const DeviceImage &image = m_document.deviceImage();
    const ImageEntry *entry = m.paired ? image.entry(m.address, &row) : nullptr;
    if (!entry)
        return {};
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(DeviceImage::Clock::now() - entry->when)
            .count();
    const QString age = seconds < 120
                            ? tr("%n second(s) ago", nullptr, static_cast<int>(seconds))
                            : tr("%n minute(s) ago", nullptr, static_cast<int>(seconds / 60));
    if (!image.connected() || entry->connection != image.connection())
        return tr("Read %1, before the connection was lost or renewed: not known to be on the "
                  "device now. Read the device again.")
            .arg(age);
    if (!image.isCurrent(*entry))
        return tr("Read %1: too old to be trusted. Read the device again.").arg(age);
    return entry->source == ImageSource::Written
               ? tr("Written %1, acknowledged by the device.").arg(age)
               : tr("Read from the device %1.").arg(age);
}

QString ParameterTreeModel::rangeText(const dev::ParamMeta &row, dev::Language lang)
{
    if (row.isString())
        return tr("text, at most %n characters", nullptr, row.length);
    if (!row.enums.empty())
        return tr("%n choices", nullptr, static_cast<int>(row.enums.size()));
    if (isBitField(row))
        return tr("bit field");
    const dev::Limits limits = dev::rowLimits(row);
    QString text = qs(dev::formatNumber(row, limits.min, lang)) + QStringLiteral(" … ") +
                   qs(dev::formatNumber(row, limits.max, lang));
    if (!row.unit.empty())
        text += QLatin1Char(' ') + qs(row.unit);
    return text;
}

QString ParameterTreeModel::helpText(int module, const dev::ParamMeta &row) const
{
    const dev::Language lang = m_document.language();
    QString text = qs(row.name) + QStringLiteral(" — ") + qs(row.label.in(lang));
    if (!row.description.in(lang).empty())
        text += QStringLiteral("\n\n") + qs(row.description.in(lang));
    text += QStringLiteral("\n\n") + tr("Address: %1").arg(qs(row.addressText()));
    text += QLatin1Char('\n') + tr("Range: %1").arg(rangeText(row, lang));
    text += QLatin1Char('\n') + tr("Access: %1").arg(qs(dev::accessText(row.access).in(lang)));
    if (row.defaultValue && !row.isString())
        text += QLatin1Char('\n') + tr("Default: %1").arg(formatRaw(row, *row.defaultValue, lang));
    if (row.scale.assumed)
        text += QLatin1Char('\n') +
                tr("The display scale depends on the installation; %1 is a typical value.")
                    .arg(qs(row.scale.name));
    if (!row.enums.empty()) {
        text += QLatin1Char('\n');
        for (const dev::EnumLabel &e : row.enums)
            text += QStringLiteral("\n%1 = %2").arg(e.value).arg(qs(e.text.in(lang)));
    }
    if (!m_document.module(module).active(row))
        text += QStringLiteral("\n\n") + tr("Not active for this module's version and mode.");
    return text;
}

QVariant ParameterTreeModel::moduleData(const Node &node, int column, int role) const
{
    const ParamModule &m = m_document.module(node.module);
    if (role == NodeKindRole)
        return static_cast<int>(NodeKind::Module);
    if (role == ModuleIndexRole)
        return node.module;
    if (role == Qt::DisplayRole) {
        if (column == ColName)
            return tr("Module %1").arg(m.address);
        if (column == ColLabel) {
            QString text = m.identity;
            if (!m.label.isEmpty())
                text = m.label + QStringLiteral(" — ") + text;
            return text + QStringLiteral(" (") + (m.online ? tr("online") : tr("offline")) +
                   QLatin1Char(')');
        }
    }
    if (role == Qt::FontRole && column == ColName) {
        QFont font;
        font.setBold(true);
        return font;
    }
    return {};
}

QVariant ParameterTreeModel::paramData(const Node &node, int column, int role) const
{
    const dev::ParamMeta &row = *node.meta;
    const int module = node.module;
    const ParamModule &m = m_document.module(module);
    const dev::Language lang = m_document.language();
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case ColName: return qs(row.name);
        case ColLabel: return qs(row.label.in(lang));
        case ColValue: return valueText(module, row, Layer::Working);
        case ColDevice: return valueText(module, row, Layer::Device);
        case ColFile: return valueText(module, row, Layer::File);
        case ColRange: return rangeText(row, m_document.language());
        case ColAccess: return qs(dev::accessText(row.access).in(lang));
        default: return {};
        }
    case Qt::EditRole:
        if (column == ColValue) {
            const auto value = m_document.value(module, &row);
            if (!value)
                return QString();
            if (const auto *text = std::get_if<std::string>(&*value))
                return qs(*text);
            if (!row.enums.empty() || isBitField(row))
                return dev::rawNumber(*value);
            return qs(dev::formatNumber(row, dev::rawNumber(*value), lang));
        }
        return paramData(node, column, Qt::DisplayRole);
    case Qt::ToolTipRole:
        if (column == ColDevice)
            if (const QString age = deviceAgeText(module, row); !age.isEmpty())
                return age;
        if (column == ColValue && isLive(m, row))
            return tr("Live value: read from the module again and again while connected.") +
                   QStringLiteral("\n\n") + helpText(module, row);
        return helpText(module, row);
    case HelpRole: return helpText(module, row);
    case Qt::ForegroundRole:
        // A device value not known now (before a reconnect, too old): grey, its age on hover.
        if (column == ColDevice && m_document.value(module, &row, Layer::Device) &&
            !m_document.deviceCurrent(module, &row))
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        // Grey is for what can be neither edited nor watched: a live value reads as live.
        if ((!row.writable() && !isLive(m, row)) || !m.active(row))
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case Qt::FontRole:
        if (m_document.changed(module, &row)) {
            QFont font;
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::BackgroundRole:
        if ((column == ColValue || column == ColDevice) &&
            m_document.differsFromDevice(module, &row))
            return QBrush(QColor(255, 236, 179)); // amber: the editor and the device disagree
        return {};
    case MetaRole: return QVariant::fromValue(reinterpret_cast<quintptr>(&row));
    case ModuleIndexRole: return module;
    case NodeKindRole: return static_cast<int>(NodeKind::Parameter);
    case RawValueRole: {
        const auto value = m_document.value(module, &row);
        if (!value)
            return {};
        if (const auto *text = std::get_if<std::string>(&*value))
            return qs(*text);
        return dev::rawNumber(*value);
    }
    case DisplayMinRole:
        return row.isString() ? QVariant() : QVariant(dev::toDisplay(row, dev::rowLimits(row).min));
    case DisplayMaxRole:
        return row.isString() ? QVariant() : QVariant(dev::toDisplay(row, dev::rowLimits(row).max));
    case DecimalsRole: return row.scale.decimals;
    case UnitRole: return qs(row.unit);
    case EnumLabelsRole: {
        QVariantList list;
        for (const dev::EnumLabel &e : row.enums)
            list.push_back(QVariantMap{{QStringLiteral("value"), static_cast<qlonglong>(e.value)},
                                       {QStringLiteral("text"), qs(e.text.in(lang))}});
        return list;
    }
    case BitLabelsRole: {
        if (!isBitField(row))
            return {};
        QVariantList list;
        for (const dev::BitLabel &b : row.bits)
            list.push_back(QVariantMap{{QStringLiteral("bit"), b.bit},
                                       {QStringLiteral("text"), qs(b.text.in(lang))}});
        return list;
    }
    case ReadOnlyRole: return !row.writable() || !m.active(row);
    case InactiveRole: return !m.active(row);
    case LiveRole: return isLive(m, row);
    case ChangedRole: return m_document.changed(module, &row);
    case DiffersFromDeviceRole: return m_document.differsFromDevice(module, &row);
    case SearchTextRole:
        return qs(row.name) + QLatin1Char('\n') + qs(row.label.en) + QLatin1Char('\n') +
               qs(row.label.de) + QLatin1Char('\n') + qs(row.description.in(lang));
    default: return {};
    }
}

QVariant ParameterTreeModel::data(const QModelIndex &index, int role) const
{
    const Node *node = nodeAt(index);
    if (!node)
        return {};
    switch (node->kind) {
    case NodeKind::Module: return moduleData(*node, index.column(), role);
    case NodeKind::Parameter: return paramData(*node, index.column(), role);
    case NodeKind::Block:
    case NodeKind::Branch:
        if (role == NodeKindRole)
            return static_cast<int>(node->kind);
        if (role == ModuleIndexRole)
            return node->module;
        if (role != Qt::DisplayRole)
            return {};
        if (node->kind == NodeKind::Block) {
            if (index.column() == ColName)
                return qs(node->block);
            if (index.column() == ColLabel)
                return blockTitle(node->block);
        } else if (index.column() == ColName) {
            return tr("Branch %1").arg(node->branch);
        }
        return {};
    }
    return {};
}

bool ParameterTreeModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const Node *node = nodeAt(index);
    if (!node || node->kind != NodeKind::Parameter || index.column() != ColValue)
        return false;
    const dev::ParamMeta &row = *node->meta;
    const dev::Language lang = m_document.language();
    dev::RawValue raw;
    if (role == RawValueRole || (role == Qt::EditRole && (value.typeId() == QMetaType::Double ||
                                                          value.typeId() == QMetaType::Int ||
                                                          value.typeId() == QMetaType::LongLong))) {
        if (row.isString())
            raw = value.toString().toStdString();
        else
            raw = value.toDouble();
    } else if (role == Qt::EditRole) {
        const std::string text = value.toString().toStdString();
        if (row.isString()) {
            raw = text;
        } else {
            const ParamParse parsed = parseParamValue(row, value.toString(), lang);
            if (!parsed.raw) {
                m_lastError = naming(row, parsed.refusal);
                emit editRefused(index, m_lastError);
                return false;
            }
            raw = *parsed.raw;
        }
    } else {
        return false;
    }
    if (auto error = m_document.edit(node->module, &row, raw)) {
        m_lastError = naming(row, *error);
        emit editRefused(index, m_lastError);
        return false;
    }
    m_lastError.clear();
    return true;
}

void ParameterTreeModel::refreshRow(int module, const dev::ParamMeta *row)
{
    const QModelIndex first = indexOf(module, row, 0);
    if (first.isValid())
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
}

void ParameterTreeModel::refreshModule(int module)
{
    for (const auto &[key, nodeIndex] : m_rowNode) {
        if (key.first != module)
            continue;
        const Node &node = m_nodes[static_cast<std::size_t>(nodeIndex)];
        const QModelIndex first = createIndex(node.row, 0, static_cast<quintptr>(nodeIndex));
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
    }
}

void ParameterTreeModel::refreshAll()
{
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        const QModelIndex first = createIndex(m_nodes[i].row, 0, static_cast<quintptr>(i));
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
    }
}

} // namespace vt::model
