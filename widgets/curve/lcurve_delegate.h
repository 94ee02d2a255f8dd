// LCurveDelegate: edits an L-curve table cell with a spin box set up from the model's roles
// (row range, decimals, raw step; numbers in the UI language, widgets/number_box.h) and greys
// fixed coordinates.
#pragma once

#include <QStyledItemDelegate>

namespace vt::ui {

class LCurveDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;

signals:
    // The typed text is not exactly a number in the UI language; the cell keeps its value.
    void refused(const QString &reason);

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override;
};

} // namespace vt::ui
