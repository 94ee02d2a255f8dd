// LCurveTableModel: the L-block curves of one module as a table in display units (row = point,
// two columns x / y per curve), editable except fixed coordinates. The parameter document
// supplies values (setValues / setRowValue) and receives every accepted user edit once
// (rowsEdited); undo stays with the document. GUI thread only; owned by its QObject parent.
#pragma once

#include "lcurve.h"

#include <QAbstractTableModel>
#include <QList>
#include <functional>
#include <optional>
#include <vector>

namespace vt::model {

// One changed dictionary row of a user edit, in display units.
struct LCurveRowEdit
{
    const dev::ParamMeta *row = nullptr;
    double display = 0;
};

class LCurveTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Role {
        RowMetaRole = Qt::UserRole + 1, // const dev::ParamMeta * as quintptr
        CurveRole,                      // int: curve index
        PointRole,                      // int: point index
        AxisRole,                       // int: 0 = x, 1 = y
        MinRole,                        // double: the row's range, display units
        MaxRole,
        DecimalsRole, // int
        StepRole,     // double: one raw step in display units
        FixedRole,    // bool: the coordinate cannot be edited
    };

    explicit LCurveTableModel(QObject *parent = nullptr);

    // The curves of `dictionary` for `version` / `mode`; values become unknown. The dictionary
    // must outlive the model (the curves point at its rows).
    void setDictionary(const dev::Dictionary &dictionary, const std::string &version,
                       const std::string &mode);
    // Curves from elsewhere (a test, no module: empty); dictionary() becomes null.
    void setCurves(std::vector<LCurve> curves);
    const std::vector<LCurve> &curves() const { return m_curves; }
    // The dictionary of the last setDictionary(); null after setCurves(). With no curves it
    // tells "this module has no curve" from "no module".
    const dev::Dictionary *dictionary() const { return m_dictionary; }
    const std::vector<LPointValue> &values(int curve) const;
    std::optional<double> value(int curve, int index, LAxis axis) const;

    // Values from outside (device read, file, undo), display units; no edit signals.
    void setValues(const std::function<std::optional<double>(const dev::ParamMeta &)> &valueOf);
    // false when `row` is not a coordinate of these curves.
    bool setRowValue(const dev::ParamMeta *row, std::optional<double> display);
    void setPoint(int curve, int index, std::optional<double> x, std::optional<double> y);

    // A user's edit (table, plot); nullopt leaves a coordinate as it is. Values are snapped to the
    // row's raster and validated; an accepted edit is stored and announced once (rowsEdited, then
    // pointEdited). Returns why it was refused (editRefused is emitted too), nullopt on success.
    std::optional<QString> editPoint(int curve, int index, std::optional<double> x,
                                     std::optional<double> y);
    LRange allowedRange(int curve, int index, LAxis axis) const;

    QModelIndex indexOf(int curve, int point, LAxis axis) const;
    int curveOfColumn(int column) const { return column / 2; }
    LAxis axisOfColumn(int column) const { return column % 2 == 0 ? LAxis::X : LAxis::Y; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // The UI language changed: headers, numbers and tooltips are asked for again.
    void retranslate();

signals:
    // One per accepted user edit, with the one or two rows it changed.
    void rowsEdited(const QList<vt::model::LCurveRowEdit> &edits);
    // After rowsEdited; the point's values after the edit (NaN where unknown).
    void pointEdited(int curve, int index, double x, double y);
    void editRefused(int curve, int index, const QString &reason);

private:
    const LCoordinate *coordinateAt(const QModelIndex &index) const;
    std::optional<double> &slot(int curve, int index, LAxis axis);
    void emitPointChanged(int curve, int index);

    std::vector<LCurve> m_curves;
    const dev::Dictionary *m_dictionary = nullptr;
    std::vector<std::vector<LPointValue>> m_values; // per curve, per point
};

} // namespace vt::model
