#include "parameter_editor.h"

#include "model/params/param_roles.h"
#include "model/params/parameter_filter_model.h"
#include "model/params/parameter_tree_model.h"
#include "param_delegate.h"

#include <QAction>
#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSplitter>
#include <QTextBrowser>
#include <QTreeView>
#include <QVBoxLayout>

namespace vt::ui {

using model::ParameterTreeModel;

ParameterEditor::ParameterEditor(model::ParameterDocument &document, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    m_tree = new ParameterTreeModel(document, this);
    m_filter = new model::ParameterFilterModel(this);
    m_filter->setSourceModel(m_tree);

    m_search = new QLineEdit(this);
    m_search->setObjectName(QStringLiteral("parameterSearch"));
    m_search->setClearButtonEnabled(true);
    m_changedOnly = new QCheckBox(this);
    m_changedOnly->setObjectName(QStringLiteral("filterChanged"));
    m_differsOnly = new QCheckBox(this);
    m_differsOnly->setObjectName(QStringLiteral("filterDiffers"));
    m_showInactive = new QCheckBox(this);
    m_showInactive->setObjectName(QStringLiteral("filterInactive"));

    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("parameterTree"));
    m_view->setModel(m_filter);
    m_view->setItemDelegateForColumn(ParameterTreeModel::ColValue, new ParamDelegate(m_view));
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    m_view->setAlternatingRowColors(true);
    m_view->setUniformRowHeights(true);
    m_view->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_view->setColumnWidth(ParameterTreeModel::ColName, 140);
    m_view->setColumnWidth(ParameterTreeModel::ColLabel, 260);
    m_view->setColumnWidth(ParameterTreeModel::ColValue, 130);
    m_view->setColumnWidth(ParameterTreeModel::ColDevice, 130);
    m_view->setColumnWidth(ParameterTreeModel::ColFile, 130);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    auto *framesAction = new QAction(m_view);
    framesAction->setObjectName(QStringLiteral("actionShowFrames"));
    m_view->addAction(framesAction);
    connect(framesAction, &QAction::triggered, this, [this] {
        const auto [module, row] = currentParameter();
        if (row)
            emit showFramesRequested(module, QString::fromStdString(row->name));
    });

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("editorMessage"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #a00000"));
    m_message->hide();

    m_help = new QTextBrowser(this);
    m_help->setObjectName(QStringLiteral("parameterHelp"));

    auto *filters = new QHBoxLayout;
    filters->addWidget(m_search, 1);
    filters->addWidget(m_changedOnly);
    filters->addWidget(m_differsOnly);
    filters->addWidget(m_showInactive);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addLayout(filters);
    leftLayout->addWidget(m_view, 1);
    leftLayout->addWidget(m_message);

    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(left);
    splitter->addWidget(m_help);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({900, 260});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);

    connect(m_search, &QLineEdit::textChanged, m_filter,
            &model::ParameterFilterModel::setSearchText);
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        if (!text.isEmpty())
            m_view->expandAll();
    });
    connect(m_changedOnly, &QCheckBox::toggled, m_filter,
            &model::ParameterFilterModel::setChangedOnly);
    connect(m_differsOnly, &QCheckBox::toggled, m_filter,
            &model::ParameterFilterModel::setDiffersFromDeviceOnly);
    connect(m_showInactive, &QCheckBox::toggled, m_filter,
            &model::ParameterFilterModel::setShowInactive);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) { onCurrentChanged(current); });
    connect(m_tree, &ParameterTreeModel::editRefused, this,
            [this](const QModelIndex &, const QString &message) {
                m_message->setText(message);
                m_message->show();
            });
    connect(&m_document, &model::ParameterDocument::valueChanged, this,
            [this] { m_message->hide(); });
    connect(m_tree, &QAbstractItemModel::modelReset, this, [this] {
        updateColumns();
        expandDefault();
    });
    connect(&m_document, &model::ParameterDocument::moduleChanged, this,
            &ParameterEditor::updateColumns);
    connect(&m_document, &model::ParameterDocument::filePathChanged, this,
            &ParameterEditor::updateColumns);
    connect(&m_document, &model::ParameterDocument::languageChanged, this,
            [this] { onCurrentChanged(m_view->currentIndex()); });
    updateColumns();
    retranslate();
}

ParameterEditor::~ParameterEditor() = default;

void ParameterEditor::expandDefault()
{
    // Modules open on their blocks; blocks stay closed until the user opens one.
    for (int r = 0; r < m_filter->rowCount(); ++r)
        m_view->expand(m_filter->index(r, 0));
}

void ParameterEditor::updateColumns()
{
    bool device = false;
    for (const model::ParamModule &m : m_document.modules())
        device = device || m.paired;
    // Device and file values side by side when both exist; the file column needs a file.
    m_view->setColumnHidden(ParameterTreeModel::ColDevice, !device);
    m_view->setColumnHidden(ParameterTreeModel::ColFile, !m_document.hasFile());
    m_differsOnly->setEnabled(device);
}

void ParameterEditor::onCurrentChanged(const QModelIndex &current)
{
    const QModelIndex source = m_filter->mapToSource(current);
    const dev::ParamMeta *row = m_tree->metaAt(source);
    m_help->setPlainText(row ? source.siblingAtColumn(0).data(model::HelpRole).toString()
                             : QString());
    if (row)
        emit parameterSelected(m_tree->moduleAt(source), row);
}

bool ParameterEditor::selectParameter(int module, const dev::ParamMeta *row)
{
    QModelIndex source = m_tree->indexOf(module, row);
    if (!source.isValid())
        return false;
    QModelIndex proxy = m_filter->mapFromSource(source);
    if (!proxy.isValid()) {
        m_search->clear();
        m_changedOnly->setChecked(false);
        m_differsOnly->setChecked(false);
        if (source.data(model::InactiveRole).toBool())
            m_showInactive->setChecked(true);
        proxy = m_filter->mapFromSource(source);
    }
    if (!proxy.isValid())
        return false;
    m_view->scrollTo(proxy);
    m_view->setCurrentIndex(proxy.siblingAtColumn(ParameterTreeModel::ColValue));
    return true;
}

std::pair<int, const dev::ParamMeta *> ParameterEditor::currentParameter() const
{
    const QModelIndex source = m_filter->mapToSource(m_view->currentIndex());
    const dev::ParamMeta *row = m_tree->metaAt(source);
    return {row ? m_tree->moduleAt(source) : -1, row};
}

void ParameterEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ParameterEditor::retranslate()
{
    m_search->setPlaceholderText(tr("Search name or text…"));
    m_changedOnly->setText(tr("Changed only"));
    m_differsOnly->setText(tr("Differs from device"));
    m_showInactive->setText(tr("Show inactive"));
    m_view->actions().constFirst()->setText(tr("Show Telegrams of This Parameter"));
}

} // namespace vt::ui
