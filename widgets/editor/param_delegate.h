// ParamDelegate: the parameter editor's value editors, built from the metadata roles the model
// exposes (param_roles.h): an enum combo, a bit-field checklist, a text field with its length,
// and a number field that shows range and unit and accepts either language's notation (the
// model parses and refuses out-of-range input, naming the limits). Read-only rows get no editor;
// live values are marked as live.
#pragma once

#include <QStyledItemDelegate>

namespace vt::ui {

class ParamDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit ParamDelegate(QObject *parent = nullptr);

    // A live value gets a small dot at the cell's end: it is watched, not disabled.
    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;
    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;
};

} // namespace vt::ui
