#include "node_view.h"

#include "dict/cooking.h"
#include "dict/identify.h"
#include "dsp408/state_machine.h"
#include "model/params/parameter_document.h"
#include "model/params/parameter_tree_model.h"
#include "model/session/identity_texts.h"

#include <QContextMenuEvent>
#include <QEvent>
#include <QHeaderView>
#include <QMenu>
#include <algorithm>

namespace vt::ui {
namespace {

// Where the device takes its control word and its set value from: "Device local" and "Device
// mode" (ED1/SD1 manual §4.2.1, §4.3.1; HART-7 manual §4.2.1, §5.2.3, §5.2.5). Shown and offered
// for the families with the DSP-408 state machine.
std::vector<const dev::ParamMeta *> modeRows(const dev::Dictionary &dictionary)
{
    std::vector<const dev::ParamMeta *> rows;
    if (!dictionary.stateControlWord())
        return rows;
    for (const char *name : {"db_Local", "db_DeviceMode"})
        if (const dev::ParamMeta *row = dictionary.find(name); row && row->readable())
            rows.push_back(row);
    return rows;
}

} // namespace

NodeView::NodeView(model::ParameterDocument &document, QWidget *parent)
    : QTreeWidget(parent), m_document(document)
{
    setObjectName(QStringLiteral("nodeView"));
    setColumnCount(6);
    setRootIsDecorated(true);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    connect(&m_document, &model::ParameterDocument::modulesReset, this, &NodeView::rebuild);
    connect(&m_document, &model::ParameterDocument::moduleChanged, this, &NodeView::rebuild);
    connect(&m_document, &model::ParameterDocument::moduleValuesChanged, this, &NodeView::rebuild);
    connect(&m_document, &model::ParameterDocument::languageChanged, this, &NodeView::rebuild);
    // Live values: only the state word column changes.
    connect(&m_document, &model::ParameterDocument::valueChanged, this,
            [this](int module, const dev::ParamMeta *row) {
                if (row && module < m_document.moduleCount() &&
                    m_document.module(module).dictionary) {
                    const dev::Dictionary &dictionary = *m_document.module(module).dictionary;
                    const auto texts = model::identityTextRows(dictionary);
                    const auto modes = modeRows(dictionary);
                    if (std::find(texts.begin(), texts.end(), row) != texts.end() ||
                        std::find(modes.begin(), modes.end(), row) != modes.end()) {
                        rebuild();
                        return;
                    }
                }
                QTreeWidgetItem *node = topLevelItem(0);
                if (node && module < node->childCount())
                    node->child(module)->setText(4, model::stateWordText(m_document, module));
            });
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        const QVariant module = item->data(0, Qt::UserRole);
        if (module.isValid())
            emit moduleActivated(module.toInt());
    });
    connect(this, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem *item) {
        const QVariant module = item->data(0, Qt::UserRole);
        if (module.isValid())
            emit moduleActivated(module.toInt());
    });
    retranslate();
}

void NodeView::setNodeText(const QString &text)
{
    m_nodeText = text;
    rebuild();
}

void NodeView::rebuild()
{
    clear();
    auto *node = new QTreeWidgetItem(this);
    node->setText(0, m_nodeText.isEmpty() ? tr("Node") : m_nodeText);
    node->setFirstColumnSpanned(true);
    for (int i = 0; i < m_document.moduleCount(); ++i) {
        const model::ParamModule &m = m_document.module(i);
        auto *item = new QTreeWidgetItem(node);
        item->setData(0, Qt::UserRole, i);
        item->setText(0, tr("Module %1").arg(m.address));
        item->setText(1,
                      m.label.isEmpty() ? QString::fromStdString(m.dictionary->family) : m.label);
        item->setText(
            2, QString::fromStdString(dev::versionText(m.version).in(m_document.language())));
        item->setText(3, QString::fromStdString(m.mode));
        item->setText(4, model::stateWordText(m_document, i));
        item->setText(5, m.online ? tr("online") : tr("offline"));
        item->setToolTip(1, m.identity);
        // The device's own texts (HART tag, long tag, descriptor, date, message) under it.
        if (m.dictionary) {
            const auto texts = model::identityTexts(
                *m.dictionary,
                [this, i](const dev::ParamMeta *row) {
                    return m_document.value(i, row, model::Layer::Device);
                },
                m_document.language());
            for (const model::IdentityText &text : texts) {
                auto *line = new QTreeWidgetItem(item);
                line->setData(0, Qt::UserRole, i);
                line->setText(0, text.label);
                line->setText(1, text.known ? text.value : tr("(not read)"));
                line->setFirstColumnSpanned(false);
            }
            for (const dev::ParamMeta *row : modeRows(*m.dictionary)) {
                const auto value = m_document.value(i, row, model::Layer::Device);
                auto *line = new QTreeWidgetItem(item);
                line->setData(0, Qt::UserRole, i);
                line->setText(0, QString::fromStdString(row->label.in(m_document.language())));
                line->setText(1, value ? QString::fromStdString(dev::formatValue(
                                             *row, dev::rawNumber(*value), m_document.language()))
                                       : tr("(not read)"));
                line->setToolTip(0, QString::fromStdString(row->name));
            }
        }
    }
    expandAll();
}

void NodeView::contextMenuEvent(QContextMenuEvent *event)
{
    QTreeWidgetItem *item = itemAt(event->pos());
    const QVariant index = item ? item->data(0, Qt::UserRole) : QVariant();
    if (!index.isValid() || index.toInt() >= m_document.moduleCount())
        return;
    const int module = index.toInt();
    const model::ParamModule &m = m_document.module(module);
    const dev::ParamMeta *control = m.dictionary ? m.dictionary->stateControlWord() : nullptr;
    if (!m.online || !control)
        return;
    // ED1/SD1 manual and HART-7 manual §4.2.2: the states a master commands with D, H, M.
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("deviceStateMenu"));
    menu.setTitle(tr("Device state"));
    menu.addSection(tr("Device state (db_ControlWord)"));
    const std::pair<dev::dsp408::State, quint16> states[] = {
        {dev::dsp408::State::Init, dev::dsp408::kControlInit},
        {dev::dsp408::State::Disabled, dev::dsp408::kControlDisabled},
        {dev::dsp408::State::Hold, dev::dsp408::kControlHold},
        {dev::dsp408::State::DeviceModeActive, dev::dsp408::kControlActive}};
    for (const auto &[state, word] : states) {
        QAction *action =
            menu.addAction(tr("%1 (control word 0x%2)")
                               .arg(QString::fromLatin1(dev::dsp408::stateName(state)))
                               .arg(word, 4, 16, QLatin1Char('0')));
        connect(action, &QAction::triggered, this,
                [this, module, w = word] { emit controlWordRequested(module, w); });
    }
    menu.addSeparator();
    QAction *reset = menu.addAction(tr("Reset fault"));
    connect(reset, &QAction::triggered, this, [this, module] { emit resetFaultRequested(module); });
    addModeMenus(menu, module);
    menu.exec(event->globalPos());
}

void NodeView::addModeMenus(QMenu &menu, int module)
{
    const model::ParamModule &m = m_document.module(module);
    const dev::Language lang = m_document.language();
    // ED1/SD1 manual §4.2.2 (DISABLED: "the different device modes like Device Mode, operating
    // mode and Device Local mode can be set"); HART-7 manual §4.2.1: "A transition to a new mode
    // is only possible if the device is in state Init or Disable".
    const dev::ParamMeta *status = m.dictionary->find("db_StatusWord");
    const auto word =
        status ? m_document.value(module, status, model::Layer::Device) : std::nullopt;
    const auto state = word ? dev::dsp408::stateOfStatusWord(static_cast<std::uint16_t>(
                                  static_cast<std::int64_t>(dev::rawNumber(*word))))
                            : std::nullopt;
    const bool changeable =
        !state || *state == dev::dsp408::State::Init || *state == dev::dsp408::State::Disabled;
    for (const dev::ParamMeta *row : modeRows(*m.dictionary)) {
        if (!row->writable() || row->enums.empty())
            continue;
        menu.addSection(tr("%1 (%2)").arg(QString::fromStdString(row->label.in(lang)),
                                          QString::fromStdString(row->name)));
        const auto held = m_document.value(module, row, model::Layer::Device);
        for (const dev::EnumLabel &option : row->enums) {
            QAction *action = menu.addAction(QString::fromStdString(option.text.in(lang)));
            action->setCheckable(true);
            action->setChecked(held && dev::rawNumber(*held) == double(option.value));
            action->setEnabled(changeable);
            connect(action, &QAction::triggered, this,
                    [this, module, name = QString::fromStdString(row->name),
                     v = double(option.value)] { emit valueRequested(module, name, v); });
        }
    }
    if (!changeable)
        menu.addAction(tr("Device local and device mode change only in INIT or DISABLED; the "
                          "device is in %1.")
                           .arg(QString::fromLatin1(dev::dsp408::stateName(*state))))
            ->setEnabled(false);
}

void NodeView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTreeWidget::changeEvent(event);
}

void NodeView::retranslate()
{
    setHeaderLabels(
        {tr("Module"), tr("Device"), tr("Version"), tr("Mode"), tr("State word"), tr("Link")});
    rebuild();
}

} // namespace vt::ui
