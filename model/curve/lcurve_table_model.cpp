#include "lcurve_table_model.h"

#include "core/vt_assert.h"
#include "model/text_language.h"

#include <QLocale>
#include <cmath>
#include <limits>

namespace vt::model {
namespace {

QString fromStd(const std::string &s)
{
    return QString::fromStdString(s);
}

double orNaN(const std::optional<double> &v)
{
    return v ? *v : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

LCurveTableModel::LCurveTableModel(QObject *parent) : QAbstractTableModel(parent)
{
}

void LCurveTableModel::retranslate()
{
    if (rowCount() == 0 || columnCount() == 0)
        return;
    emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
    emit headerDataChanged(Qt::Vertical, 0, rowCount() - 1);
    emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1),
                     {Qt::DisplayRole, Qt::ToolTipRole});
}

void LCurveTableModel::setDictionary(const dev::Dictionary &dictionary, const std::string &version,
                                     const std::string &mode)
{
    beginResetModel();
    m_curves = findLCurves(dictionary, version, mode);
    m_dictionary = &dictionary;
    m_values.assign(m_curves.size(), {});
    for (std::size_t c = 0; c < m_curves.size(); ++c)
        m_values[c].resize(m_curves[c].points.size());
    endResetModel();
}

void LCurveTableModel::setCurves(std::vector<LCurve> curves)
{
    beginResetModel();
    m_curves = std::move(curves);
    m_dictionary = nullptr;
    m_values.assign(m_curves.size(), {});
    for (std::size_t c = 0; c < m_curves.size(); ++c)
        m_values[c].resize(m_curves[c].points.size());
    endResetModel();
}

const std::vector<LPointValue> &LCurveTableModel::values(int curve) const
{
    static const std::vector<LPointValue> none;
    if (curve < 0 || curve >= static_cast<int>(m_values.size()))
        return none;
    return m_values[static_cast<std::size_t>(curve)];
}

std::optional<double> LCurveTableModel::value(int curve, int index, LAxis axis) const
{
    const auto &v = values(curve);
    if (index < 0 || index >= static_cast<int>(v.size()))
        return std::nullopt;
    const LPointValue &p = v[static_cast<std::size_t>(index)];
    return axis == LAxis::X ? p.x : p.y;
}

std::optional<double> &LCurveTableModel::slot(int curve, int index, LAxis axis)
{
    LPointValue &p = m_values[static_cast<std::size_t>(curve)][static_cast<std::size_t>(index)];
    return axis == LAxis::X ? p.x : p.y;
}

void LCurveTableModel::emitPointChanged(int curve, int index)
{
    emit dataChanged(indexOf(curve, index, LAxis::X), indexOf(curve, index, LAxis::Y));
}

void LCurveTableModel::setValues(
    const std::function<std::optional<double>(const dev::ParamMeta &)> &valueOf)
{
    for (std::size_t c = 0; c < m_curves.size(); ++c) {
        for (std::size_t i = 0; i < m_curves[c].points.size(); ++i) {
            const LPoint &p = m_curves[c].points[i];
            m_values[c][i] = {valueOf(*p.x.row), valueOf(*p.y.row)};
        }
    }
    if (rowCount() > 0 && columnCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

bool LCurveTableModel::setRowValue(const dev::ParamMeta *row, std::optional<double> display)
{
    for (std::size_t c = 0; c < m_curves.size(); ++c) {
        for (std::size_t i = 0; i < m_curves[c].points.size(); ++i) {
            for (const LAxis axis : {LAxis::X, LAxis::Y}) {
                if (coordinate(m_curves[c].points[i], axis).row != row)
                    continue;
                slot(static_cast<int>(c), static_cast<int>(i), axis) = display;
                emitPointChanged(static_cast<int>(c), static_cast<int>(i));
                return true;
            }
        }
    }
    return false;
}

void LCurveTableModel::setPoint(int curve, int index, std::optional<double> x,
                                std::optional<double> y)
{
    if (!indexOf(curve, index, LAxis::X).isValid())
        return;
    m_values[static_cast<std::size_t>(curve)][static_cast<std::size_t>(index)] = {x, y};
    emitPointChanged(curve, index);
}

std::optional<QString> LCurveTableModel::editPoint(int curve, int index, std::optional<double> x,
                                                   std::optional<double> y)
{
    if (!indexOf(curve, index, LAxis::X).isValid()) {
        const QString why = tr("no such point");
        emit editRefused(curve, index, why);
        return why;
    }
    const LCurve &c = m_curves[static_cast<std::size_t>(curve)];
    const LPoint &point = c.points[static_cast<std::size_t>(index)];
    // Check against the values as they will be: x first (order), then y.
    std::vector<LPointValue> next = m_values[static_cast<std::size_t>(curve)];
    QList<LCurveRowEdit> edits;
    for (const LAxis axis : {LAxis::X, LAxis::Y}) {
        const std::optional<double> &typed = axis == LAxis::X ? x : y;
        if (!typed)
            continue;
        const LCoordinate &coord = coordinate(point, axis);
        const double snapped = snapToStep(coord, *typed);
        if (auto why = checkCoordinate(c, next, index, axis, snapped, textLanguage())) {
            emit editRefused(curve, index, *why);
            return why;
        }
        LPointValue &p = next[static_cast<std::size_t>(index)];
        std::optional<double> &target = axis == LAxis::X ? p.x : p.y;
        if (target && std::abs(*target - snapped) < coord.step / 2)
            continue; // unchanged (also a fixed coordinate given its own value)
        target = snapped;
        edits.push_back({coord.row, snapped});
    }
    if (edits.isEmpty())
        return std::nullopt;
    m_values[static_cast<std::size_t>(curve)] = std::move(next);
    emitPointChanged(curve, index);
    emit rowsEdited(edits);
    const LPointValue &now =
        m_values[static_cast<std::size_t>(curve)][static_cast<std::size_t>(index)];
    emit pointEdited(curve, index, orNaN(now.x), orNaN(now.y));
    return std::nullopt;
}

LRange LCurveTableModel::allowedRange(int curve, int index, LAxis axis) const
{
    if (curve < 0 || curve >= static_cast<int>(m_curves.size()))
        return {1, 0};
    const auto c = static_cast<std::size_t>(curve);
    return model::allowedRange(m_curves[c], m_values[c], index, axis);
}

QModelIndex LCurveTableModel::indexOf(int curve, int point, LAxis axis) const
{
    if (curve < 0 || curve >= static_cast<int>(m_curves.size()) || point < 0 ||
        point >= static_cast<int>(m_curves[static_cast<std::size_t>(curve)].points.size()))
        return {};
    return index(point, curve * 2 + (axis == LAxis::X ? 0 : 1));
}

const LCoordinate *LCurveTableModel::coordinateAt(const QModelIndex &index) const
{
    if (!index.isValid())
        return nullptr;
    VT_ASSERT(index.model() == this, return nullptr);
    const auto c = static_cast<std::size_t>(curveOfColumn(index.column()));
    const auto i = static_cast<std::size_t>(index.row());
    if (c >= m_curves.size() || i >= m_curves[c].points.size())
        return nullptr; // a shorter curve leaves cells empty
    return &coordinate(m_curves[c].points[i], axisOfColumn(index.column()));
}

int LCurveTableModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid())
        return 0;
    std::size_t rows = 0;
    for (const LCurve &c : m_curves)
        rows = std::max(rows, c.points.size());
    return static_cast<int>(rows);
}

int LCurveTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_curves.size()) * 2;
}

QVariant LCurveTableModel::data(const QModelIndex &index, int role) const
{
    const LCoordinate *coord = coordinateAt(index);
    if (!coord)
        return {};
    const int curve = curveOfColumn(index.column());
    const LAxis axis = axisOfColumn(index.column());
    const std::optional<double> v = value(curve, index.row(), axis);
    switch (role) {
    case Qt::DisplayRole: return v ? QLocale().toString(*v, 'f', coord->decimals) : QString();
    case Qt::EditRole: return v ? QVariant(*v) : QVariant();
    case Qt::TextAlignmentRole: return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::ToolTipRole: {
        const dev::Language lang = textLanguage();
        QString tip =
            fromStd(coord->row->name) + QStringLiteral(": ") + fromStd(coord->row->label.in(lang));
        if (coord->fixed())
            tip += QLatin1Char('\n') + fixedText(*coord, lang);
        return tip;
    }
    case RowMetaRole: return QVariant::fromValue(reinterpret_cast<quintptr>(coord->row));
    case CurveRole: return curve;
    case PointRole: return index.row();
    case AxisRole: return axis == LAxis::X ? 0 : 1;
    case MinRole: return coord->min;
    case MaxRole: return coord->max;
    case DecimalsRole: return coord->decimals;
    case StepRole: return coord->step;
    case FixedRole: return coord->fixed();
    default: return {};
    }
}

bool LCurveTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || !coordinateAt(index))
        return false;
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok)
        return false;
    const int curve = curveOfColumn(index.column());
    const bool isX = axisOfColumn(index.column()) == LAxis::X;
    return !editPoint(curve, index.row(), isX ? std::optional(v) : std::nullopt,
                      isX ? std::nullopt : std::optional(v))
                .has_value();
}

Qt::ItemFlags LCurveTableModel::flags(const QModelIndex &index) const
{
    const LCoordinate *coord = coordinateAt(index);
    if (!coord)
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (!coord->fixed())
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant LCurveTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    if (orientation == Qt::Vertical) {
        if (section < 0 || section >= rowCount())
            return {};
        return role == Qt::DisplayRole ? tr("P%1").arg(section) : tr("Point %1").arg(section);
    }
    if (section < 0 || section >= columnCount())
        return {};
    const LCurve &c = m_curves[static_cast<std::size_t>(curveOfColumn(section))];
    const bool isX = axisOfColumn(section) == LAxis::X;
    if (role == Qt::ToolTipRole)
        return isX ? tr("%1: input (set value) coordinate, branch %2")
                         .arg(fromStd(c.name))
                         .arg(c.branch)
                   : tr("%1: output coordinate, branch %2").arg(fromStd(c.name)).arg(c.branch);
    return isX ? tr("%1 x (%2)").arg(fromStd(c.name), fromStd(c.unit))
               : tr("%1 y (%2)").arg(fromStd(c.name), fromStd(c.unit));
}

} // namespace vt::model
