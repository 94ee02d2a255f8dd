#include "channel_chooser.h"

#include "dict/identify.h"
#include "model/text_language.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace vt::ui {

namespace {

constexpr int kRowRole = Qt::UserRole + 1;     // const dev::ParamMeta *
constexpr int kModuleRole = Qt::UserRole + 2;  // int
constexpr int kFamilyRole = Qt::UserRole + 3;  // QString, on a module's row
constexpr int kVersionRole = Qt::UserRole + 4; // QString, on a module's row

const dev::ParamMeta *rowOf(const QTreeWidgetItem *item)
{
    return static_cast<const dev::ParamMeta *>(item->data(0, kRowRole).value<const void *>());
}

} // namespace

ChannelChooser::ChannelChooser(const std::vector<model::ModuleInfo> &modules,
                               const ChannelSelection &offered, const ChannelSelection &selected,
                               dev::Language lang, QWidget *parent)
    : QDialog(parent)
{
    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    m_tree = new QTreeWidget(this);
    m_tree->setColumnCount(3);
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    for (const model::ModuleInfo &module : modules) {
        auto it = offered.find(module.address);
        if (it == offered.end())
            continue;
        auto *top = new QTreeWidgetItem(m_tree);
        top->setData(0, kModuleRole, module.address);
        // The module's own row names it; its version belongs beside the family, not under the
        // rows' "Unit" heading (retranslate() writes the texts).
        top->setData(1, kFamilyRole, QString::fromStdString(module.identification.family));
        top->setData(1, kVersionRole, QString::fromStdString(module.identification.version));
        const auto chosen = selected.find(module.address);
        for (const dev::ParamMeta *row : it->second) {
            auto *child = new QTreeWidgetItem(top);
            child->setData(0, kRowRole, QVariant::fromValue(static_cast<const void *>(row)));
            child->setData(0, kModuleRole, module.address);
            child->setText(0, QString::fromStdString(row->name));
            child->setText(1, QString::fromStdString(row->label.in(lang)));
            child->setText(2, QString::fromStdString(row->unit));
            const bool on = chosen != selected.end() &&
                            std::find(chosen->second.begin(), chosen->second.end(), row) !=
                                chosen->second.end();
            child->setCheckState(0, on ? Qt::Checked : Qt::Unchecked);
        }
        top->setExpanded(true);
    }
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_hint);
    layout->addWidget(m_tree);
    layout->addWidget(buttons);
    resize(520, 480);
    retranslate();
}

ChannelSelection ChannelChooser::selection() const
{
    ChannelSelection out;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem *top = m_tree->topLevelItem(i);
        std::vector<const dev::ParamMeta *> rows;
        for (int j = 0; j < top->childCount(); ++j) {
            if (top->child(j)->checkState(0) == Qt::Checked)
                rows.push_back(rowOf(top->child(j)));
        }
        if (!rows.empty())
            out[top->data(0, kModuleRole).toInt()] = std::move(rows);
    }
    return out;
}

void ChannelChooser::setChecked(int module, const std::vector<const dev::ParamMeta *> &rows)
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem *top = m_tree->topLevelItem(i);
        if (top->data(0, kModuleRole).toInt() != module)
            continue;
        for (int j = 0; j < top->childCount(); ++j) {
            const bool on = std::find(rows.begin(), rows.end(), rowOf(top->child(j))) != rows.end();
            top->child(j)->setCheckState(0, on ? Qt::Checked : Qt::Unchecked);
        }
    }
}

void ChannelChooser::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ChannelChooser::retranslate()
{
    setWindowTitle(tr("Monitor channels"));
    m_hint->setText(
        tr("Tick the live values to plot. Each module is polled in one request per sample, "
           "so more modules share the link's rate; changing a module's channels starts its "
           "recording anew."));
    m_tree->setHeaderLabels({tr("Value"), tr("Name"), tr("Unit")});
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem *top = m_tree->topLevelItem(i);
        top->setText(0, tr("Module %1").arg(top->data(0, kModuleRole).toInt()));
        const QString family = top->data(1, kFamilyRole).toString();
        // The version as the family writes it ("V51.00", "capability 0x00130000"), in the language.
        const std::string raw = top->data(1, kVersionRole).toString().toStdString();
        const QString version =
            QString::fromStdString(dev::versionText(raw).in(model::textLanguage()));
        top->setText(1, raw.empty() ? family : QStringLiteral("%1, %2").arg(family, version));
    }
}

} // namespace vt::ui
