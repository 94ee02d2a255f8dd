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
#include <QStyle>
#include <QTextBrowser>
#include <QTimer>
#include <QTreeView>
#include <QVBoxLayout>
#include <algorithm>
#include <functional>
#include <iterator>

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

    // F1 on a parameter: its help beside the tree, opened again if the user had closed it.
    auto *helpAction = new QAction(m_view);
    helpAction->setObjectName(QStringLiteral("actionParameterHelp"));
    helpAction->setShortcut(QKeySequence::HelpContents);
    helpAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_view->addAction(helpAction);
    connect(helpAction, &QAction::triggered, this, &ParameterEditor::showHelpOfCurrent);

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
    m_splitter = splitter;
    splitter->setObjectName(QStringLiteral("editorSplitter"));
    splitter->addWidget(left);
    splitter->addWidget(m_help);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({900, 260});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);

    // A filter brings rows back collapsed: each change restores the blocks the user had open
    // (a search shows every match, opened).
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_filter->setSearchText(text);
        restoreExpansion();
    });
    connect(m_changedOnly, &QCheckBox::toggled, this, [this](bool on) {
        m_filter->setChangedOnly(on);
        restoreExpansion();
    });
    connect(m_differsOnly, &QCheckBox::toggled, this, [this](bool on) {
        m_filter->setDiffersFromDeviceOnly(on);
        restoreExpansion();
    });
    connect(m_showInactive, &QCheckBox::toggled, this, [this](bool on) {
        m_filter->setShowInactive(on);
        restoreExpansion();
    });
    connect(m_view, &QTreeView::expanded, this, [this](const QModelIndex &index) {
        if (!m_restoring && m_search->text().isEmpty())
            m_expanded.insert(expansionKey(index));
    });
    connect(m_view, &QTreeView::collapsed, this, [this](const QModelIndex &index) {
        if (!m_restoring && m_search->text().isEmpty())
            m_expanded.remove(expansionKey(index));
    });
    // Rows a value change lets through the "changed" filters come back as the user left them.
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, [this] {
        if (m_restorePending)
            return;
        m_restorePending = true;
        QTimer::singleShot(0, this, [this] {
            m_restorePending = false;
            restoreExpansion();
        });
    });
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
        fitValueColumns();
        expandDefault();
    });
    connect(&m_document, &model::ParameterDocument::moduleChanged, this,
            &ParameterEditor::updateColumns);
    connect(&m_document, &model::ParameterDocument::filePathChanged, this,
            &ParameterEditor::updateColumns);
    connect(&m_document, &model::ParameterDocument::languageChanged, this, [this] {
        onCurrentChanged(m_view->currentIndex());
        fitValueColumns();
    });
    updateColumns();
    retranslate();
}

ParameterEditor::~ParameterEditor() = default;

void ParameterEditor::expandDefault()
{
    // Modules open on their blocks; blocks stay closed until the user opens one, and those the
    // user opened stay open across an Open or a reconnect.
    for (int r = 0; r < m_filter->rowCount(); ++r)
        m_expanded.insert(expansionKey(m_filter->index(r, 0)));
    restoreExpansion();
}

void ParameterEditor::fitValueColumns()
{
    // Values and ranges readable without dragging: each column at least as wide as its longest
    // text (within reason); a column the user widened stays as wide.
    constexpr int kMaxWidth = 340;
    const QFontMetrics metrics = m_view->fontMetrics();
    const int padding = 2 * m_view->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 24;
    const int columns[] = {ParameterTreeModel::ColValue, ParameterTreeModel::ColDevice,
                           ParameterTreeModel::ColFile, ParameterTreeModel::ColRange,
                           ParameterTreeModel::ColAccess};
    int widths[std::size(columns)] = {};
    std::function<void(const QModelIndex &)> measure = [&](const QModelIndex &parent) {
        for (int r = 0; r < m_tree->rowCount(parent); ++r) {
            const QModelIndex row = m_tree->index(r, 0, parent);
            for (std::size_t c = 0; c < std::size(columns); ++c)
                widths[c] = qMax(widths[c], metrics.horizontalAdvance(
                                                row.siblingAtColumn(columns[c]).data().toString()));
            measure(row);
        }
    };
    measure({});
    widths[0] = std::max({widths[0], widths[1], widths[2]}); // the three value columns alike
    widths[1] = widths[2] = widths[0];
    // The header's own font and margins: "Access" / "Zugriff" is never cut.
    const QFontMetrics headerMetrics = m_view->header()->fontMetrics();
    const int headerPadding = 2 * m_view->style()->pixelMetric(QStyle::PM_HeaderMargin);
    for (std::size_t c = 0; c < std::size(columns); ++c) {
        const int header =
            headerPadding + headerMetrics.horizontalAdvance(
                                m_tree->headerData(columns[c], Qt::Horizontal).toString());
        const int want = qMin(kMaxWidth, qMax(widths[c], header) + padding);
        if (m_view->columnWidth(columns[c]) < want)
            m_view->setColumnWidth(columns[c], want);
    }
}

QString ParameterEditor::expansionKey(const QModelIndex &proxy) const
{
    // The source rows' path: the same under every filter, and in either language.
    QStringList path;
    for (QModelIndex i = m_filter->mapToSource(proxy); i.isValid(); i = i.parent())
        path.prepend(QString::number(i.row()));
    return path.join(QLatin1Char('/'));
}

void ParameterEditor::restoreExpansion()
{
    m_restoring = true;
    const bool searching = !m_search->text().isEmpty();
    std::function<void(const QModelIndex &)> apply = [&](const QModelIndex &parent) {
        for (int r = 0; r < m_filter->rowCount(parent); ++r) {
            const QModelIndex child = m_filter->index(r, 0, parent);
            if (!m_filter->hasChildren(child))
                continue;
            m_view->setExpanded(child, searching || m_expanded.contains(expansionKey(child)));
            apply(child);
        }
    };
    apply({});
    m_restoring = false;
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

void ParameterEditor::showHelpOfCurrent()
{
    onCurrentChanged(m_view->currentIndex());
    QList<int> sizes = m_splitter->sizes();
    if (sizes.size() == 2 && sizes[1] < 80) {
        const int total = sizes[0] + sizes[1];
        m_splitter->setSizes({total - 300, 300});
    }
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
    m_view->actions().at(1)->setText(tr("Help on This Parameter"));
}

} // namespace vt::ui
