#include "widgets/fold/fold_options_page.h"

#include "dict/cooking.h"
#include "dict/dictionary.h"
#include "model/text_language.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/number_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace vt::ui {

FoldOptionsPage::FoldOptionsPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    // The explanations wrap to the page width instead of widening it.
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(m_scroll);
    retranslate();
}

void FoldOptionsPage::initializePage()
{
    rebuild();
}

void FoldOptionsPage::rebuild()
{
    FoldWizard *wizard = fold();
    if (!wizard)
        return;
    const model::FoldPlan &plan = wizard->plan();
    m_content = new QWidget;
    auto *layout = new QVBoxLayout(m_content);
    for (std::size_t index = 0; index < plan.modules.size(); ++index) {
        const model::FoldModule &module = plan.modules[index];
        auto *box = new QGroupBox(m_content);
        box->setObjectName(QStringLiteral("module%1").arg(index + 1));
        box->setTitle(tr("Module %1 — %2, V%3, mode %4")
                          .arg(index + 1)
                          .arg(model::foldAddressText(plan.node, module))
                          .arg(module.version)
                          .arg(module.mode));
        auto *grid = new QGridLayout(box);
        grid->setColumnStretch(2, 1);
        layout->addWidget(box);
        const dev::Dictionary *dictionary =
            model::foldDictionary(wizard->dictionaries(), plan.node, module);
        if (!dictionary) {
            grid->addWidget(
                new QLabel(
                    tr("No parameter list for this software version: options cannot be set."), box),
                0, 0);
            continue;
        }
        int line = 0;
        for (const std::string &name : model::foldOptionNames(plan.node, index)) {
            const dev::ParamMeta *row = dictionary->find(name);
            if (!row)
                continue;
            const QString key = QString::fromStdString(name);
            auto *set = new QCheckBox(
                QStringLiteral("%1 — %2").arg(key, model::localText(row->label)), box);
            set->setObjectName(QStringLiteral("set%1").arg(key));
            grid->addWidget(set, line, 0, 1, 3);
            ++line;
            const std::optional<int> value = model::foldOption(module.options, name);
            set->setChecked(value.has_value());
            QWidget *editor = nullptr;
            auto *cooked = new QLabel(box);
            const int fallback = static_cast<int>(row->defaultValue.value_or(row->min));
            const auto store = [this, index, name, set](int raw) {
                model::FoldPlan &p = fold()->editPlan();
                if (index < p.modules.size())
                    model::setFoldOption(p.modules[index].options, name,
                                         set->isChecked() ? std::optional<int>(raw) : std::nullopt);
            };
            if (!row->enums.empty()) {
                auto *combo = new QComboBox(box);
                // Long enum labels (E28) must not widen the page past its width.
                combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                combo->setMinimumContentsLength(24);
                for (const dev::EnumLabel &label : row->enums)
                    combo->addItem(QStringLiteral("%1 = %2")
                                       .arg(label.value)
                                       .arg(model::localText(label.text)),
                                   static_cast<int>(label.value));
                combo->setCurrentIndex(std::max(0, combo->findData(value.value_or(fallback))));
                connect(combo, &QComboBox::currentIndexChanged, this,
                        [combo, store] { store(combo->currentData().toInt()); });
                connect(set, &QCheckBox::toggled, this, [combo, store](bool on) {
                    combo->setEnabled(on);
                    store(combo->currentData().toInt());
                });
                combo->setEnabled(set->isChecked());
                editor = combo;
            } else {
                auto *spin = new WholeNumberBox(box);
                const dev::Limits limits = dev::rowLimits(*row);
                spin->setRange(static_cast<int>(std::ceil(limits.min)),
                               static_cast<int>(std::floor(limits.max)));
                spin->setValue(value.value_or(fallback));
                const auto showCooked = [spin, cooked, row] {
                    cooked->setText(QStringLiteral("= %1").arg(QString::fromStdString(
                        dev::formatValue(*row, spin->value(), model::textLanguage()))));
                };
                showCooked();
                connect(spin, &QSpinBox::valueChanged, this, [spin, store, showCooked] {
                    showCooked();
                    store(spin->value());
                });
                connect(set, &QCheckBox::toggled, this, [spin, store](bool on) {
                    spin->setEnabled(on);
                    store(spin->value());
                });
                spin->setEnabled(set->isChecked());
                editor = spin;
            }
            editor->setObjectName(QStringLiteral("edit%1").arg(key));
            grid->addWidget(editor, line, 0);
            grid->addWidget(cooked, line, 1);
            ++line;
            // The manual's consequence of the option, from the dictionary (both languages).
            auto *why = new QLabel(model::localText(row->description), box);
            why->setWordWrap(true);
            why->setObjectName(QStringLiteral("why%1").arg(key));
            grid->addWidget(why, line, 0, 1, 3);
            ++line;
        }
        if (line == 0)
            grid->addWidget(new QLabel(tr("This module has no bus options to set."), box), 0, 0);
    }
    layout->addStretch();
    m_scroll->setWidget(m_content); // deletes the previous content
}

void FoldOptionsPage::retranslate()
{
    setTitle(tr("Options"));
    setSubTitle(tr("Tick an option to write it. Unticked options stay as they are on the module."));
    if (fold() && m_content)
        rebuild();
}

} // namespace vt::ui
