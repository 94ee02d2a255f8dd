#include "param_delegate.h"

#include "model/params/param_roles.h"

#include <QComboBox>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPainter>

namespace vt::ui {
namespace {

constexpr const char *kKind = "vtEditorKind";

QString rangeHint(const QModelIndex &index)
{
    const QVariant min = index.data(model::DisplayMinRole);
    const QVariant max = index.data(model::DisplayMaxRole);
    if (!min.isValid() || !max.isValid())
        return {};
    const int decimals = index.data(model::DecimalsRole).toInt();
    const QLocale locale;
    QString text = locale.toString(min.toDouble(), 'f', decimals) + QStringLiteral(" … ") +
                   locale.toString(max.toDouble(), 'f', decimals);
    const QString unit = index.data(model::UnitRole).toString();
    if (!unit.isEmpty())
        text += QLatin1Char(' ') + unit;
    return text;
}

} // namespace

ParamDelegate::ParamDelegate(QObject *parent) : QStyledItemDelegate(parent)
{
}

void ParamDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const
{
    QStyledItemDelegate::paint(painter, option, index);
    if (!index.data(model::LiveRole).toBool())
        return;
    const int d = qMax(4, option.rect.height() / 4);
    const QRect dot(option.rect.right() - d - 4, option.rect.center().y() - d / 2, d, d);
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(Qt::NoPen);
    painter->setBrush(QColor(46, 160, 67)); // a quiet green, the colour of "running"
    painter->drawEllipse(dot);
    painter->restore();
}

QWidget *ParamDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                     const QModelIndex &index) const
{
    if (index.data(model::ReadOnlyRole).toBool() || !(index.flags() & Qt::ItemIsEditable))
        return nullptr;
    const QVariantList enums = index.data(model::EnumLabelsRole).toList();
    if (!enums.isEmpty()) {
        auto *combo = new QComboBox(parent);
        combo->setProperty(kKind, QStringLiteral("enum"));
        for (const QVariant &e : enums) {
            const QVariantMap m = e.toMap();
            combo->addItem(QStringLiteral("%1 — %2")
                               .arg(m.value(QStringLiteral("value")).toLongLong())
                               .arg(m.value(QStringLiteral("text")).toString()),
                           m.value(QStringLiteral("value")));
        }
        return combo;
    }
    const QVariantList bits = index.data(model::BitLabelsRole).toList();
    if (!bits.isEmpty()) {
        auto *list = new QListWidget(parent);
        list->setProperty(kKind, QStringLiteral("bits"));
        for (const QVariant &b : bits) {
            const QVariantMap m = b.toMap();
            auto *item = new QListWidgetItem(QStringLiteral("%1: %2")
                                                 .arg(m.value(QStringLiteral("bit")).toInt())
                                                 .arg(m.value(QStringLiteral("text")).toString()),
                                             list);
            item->setData(Qt::UserRole, m.value(QStringLiteral("bit")));
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            item->setCheckState(Qt::Unchecked);
        }
        return list;
    }
    auto *edit = new QLineEdit(parent);
    edit->setProperty(kKind, QStringLiteral("text"));
    edit->setPlaceholderText(rangeHint(index));
    edit->setToolTip(rangeHint(index));
    Q_UNUSED(option)
    return edit;
}

void ParamDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    const QString kind = editor->property(kKind).toString();
    if (kind == QLatin1String("enum")) {
        auto *combo = static_cast<QComboBox *>(editor);
        const int at = combo->findData(index.data(model::RawValueRole).toLongLong());
        combo->setCurrentIndex(at);
    } else if (kind == QLatin1String("bits")) {
        auto *list = static_cast<QListWidget *>(editor);
        const auto raw = static_cast<quint32>(index.data(model::RawValueRole).toLongLong());
        for (int i = 0; i < list->count(); ++i) {
            const int bit = list->item(i)->data(Qt::UserRole).toInt();
            list->item(i)->setCheckState((raw >> bit) & 1u ? Qt::Checked : Qt::Unchecked);
        }
    } else if (auto *edit = qobject_cast<QLineEdit *>(editor)) {
        edit->setText(index.data(Qt::EditRole).toString());
        edit->selectAll();
    }
}

void ParamDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                 const QModelIndex &index) const
{
    const QString kind = editor->property(kKind).toString();
    if (kind == QLatin1String("enum")) {
        auto *combo = static_cast<QComboBox *>(editor);
        if (combo->currentIndex() >= 0)
            model->setData(index, combo->currentData().toDouble(), Qt::EditRole);
    } else if (kind == QLatin1String("bits")) {
        auto *list = static_cast<QListWidget *>(editor);
        auto raw = static_cast<quint32>(index.data(model::RawValueRole).toLongLong());
        for (int i = 0; i < list->count(); ++i) {
            const int bit = list->item(i)->data(Qt::UserRole).toInt();
            if (list->item(i)->checkState() == Qt::Checked)
                raw |= 1u << bit;
            else
                raw &= ~(1u << bit);
        }
        model->setData(index, static_cast<double>(raw), Qt::EditRole);
    } else if (auto *edit = qobject_cast<QLineEdit *>(editor)) {
        // The model parses in the document's language and refuses with the limits named.
        model->setData(index, edit->text(), Qt::EditRole);
    }
}

void ParamDelegate::updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                                         const QModelIndex &index) const
{
    if (editor->property(kKind).toString() == QLatin1String("bits")) {
        auto *list = static_cast<QListWidget *>(editor);
        const int rowHeight = qMax(list->sizeHintForRow(0), option.rect.height());
        QRect r = option.rect;
        r.setHeight(qMin(list->count(), 10) * rowHeight + 2 * list->frameWidth());
        r.setWidth(qMax(r.width(), list->sizeHintForColumn(0) + 30));
        editor->setGeometry(r);
        return;
    }
    QStyledItemDelegate::updateEditorGeometry(editor, option, index);
}

} // namespace vt::ui
