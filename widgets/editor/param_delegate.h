// ParamDelegate: the parameter editor's value editors, built from the metadata roles the model
// exposes (param_roles.h): an enum combo, a bit-field checklist, a text field with its length,
// and a number field that shows range and unit and accepts either language's notation (the
// model parses and refuses out-of-range input, naming the limits). Read-only rows get no editor.
#pragma once

#include <QStyledItemDelegate>

namespace vt::ui {

class ParamDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit ParamDelegate(QObject *parent = nullptr);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;
};

} // namespace vt::ui
