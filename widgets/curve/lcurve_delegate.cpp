#include "lcurve_delegate.h"

#include "core/vt_assert.h"
#include "model/curve/lcurve_table_model.h"
#include "widgets/number_box.h"

namespace vt::ui {

using Model = model::LCurveTableModel;

QWidget *LCurveDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &,
                                      const QModelIndex &index) const
{
    auto *box = new NumberBox(parent);
    box->setFrame(false);
    box->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    box->setDecimals(index.data(Model::DecimalsRole).toInt());
    // The row's own range only: a value between the wrong neighbours reaches the model, which
    // refuses it and says why (editRefused), instead of the spin box silently clamping it.
    box->setRange(index.data(Model::MinRole).toDouble(), index.data(Model::MaxRole).toDouble());
    box->setSingleStep(index.data(Model::StepRole).toDouble());
    return box;
}

void LCurveDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    if (auto *box = qobject_cast<NumberBox *>(editor))
        box->setValue(index.data(Qt::EditRole).toDouble());
}

void LCurveDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                  const QModelIndex &index) const
{
    auto *box = qobject_cast<NumberBox *>(editor);
    VT_ASSERT(box, return ); // createEditor() made it
    // Not exactly a number in the UI language: nothing reaches the model, the reason is said.
    const std::optional<double> typed = box->number();
    if (!typed) {
        emit const_cast<LCurveDelegate *>(this)->refused(box->refusal());
        return;
    }
    model->setData(index, *typed, Qt::EditRole);
}

void LCurveDelegate::initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    if (index.data(Model::FixedRole).toBool())
        option->palette.setColor(QPalette::Text,
                                 option->palette.color(QPalette::Disabled, QPalette::Text));
}

} // namespace vt::ui
