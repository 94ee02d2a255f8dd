#include "inspector_view.h"

#include "compose_panel.h"
#include "decode_panel.h"
#include "dict/dictionary.h"
#include "frame_detail.h"
#include "inspect/frame_parameters.h"
#include "inspect/logged_frame.h"
#include "model/inspect/frame_links.h"
#include "model/session/connection.h"
#include "model/telegrams/telegram_log_model.h"
#include "model/text_language.h"
#include "transports/byte_span.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

namespace vt::ui {

InspectorView::InspectorView(QWidget *parent)
    : QWidget(parent), m_moduleLabel(new QLabel(this)), m_moduleFilter(new QComboBox(this)),
      m_protocolLabel(new QLabel(this)), m_protocolFilter(new QComboBox(this)),
      m_errorsOnly(new QCheckBox(this)), m_pause(new QPushButton(this)),
      m_clear(new QPushButton(this)), m_saveCsv(new QPushButton(this)),
      m_saveText(new QPushButton(this)), m_goTo(new QPushButton(this)),
      m_table(new QTableView(this)), m_tabs(new QTabWidget(this)), m_detail(new FrameDetail(this)),
      m_decode(new DecodePanel(this)), m_compose(new ComposePanel(this))
{
    m_moduleFilter->addItem(QString(), -1);
    m_protocolFilter->addItem(QString(), QString());
    for (vt::dev::LinkProtocol protocol : vt::dev::kLinkProtocols) {
        const QString key = QString::fromLatin1(vt::dev::key(protocol));
        m_protocolFilter->addItem(key, key);
    }
    m_pause->setCheckable(true);
    m_pause->setEnabled(false);
    m_clear->setEnabled(false);
    m_saveCsv->setEnabled(false);
    m_saveText->setEnabled(false);
    m_goTo->setEnabled(false);

    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    m_table->setWordWrap(false);

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_moduleLabel);
    bar->addWidget(m_moduleFilter);
    bar->addWidget(m_protocolLabel);
    bar->addWidget(m_protocolFilter);
    bar->addWidget(m_errorsOnly);
    bar->addStretch(1);
    bar->addWidget(m_goTo);
    bar->addWidget(m_pause);
    bar->addWidget(m_clear);
    bar->addWidget(m_saveCsv);
    bar->addWidget(m_saveText);

    m_tabs->addTab(m_detail, QString());
    m_tabs->addTab(m_decode, QString());
    m_tabs->addTab(m_compose, QString());
    // Side by side: the dock is wide and low, and the list keeps the dock's whole height for rows.
    m_table->setObjectName(QStringLiteral("telegramTable"));
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName(QStringLiteral("inspectorSplitter"));
    split->addWidget(m_table);
    split->addWidget(m_tabs);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setSizes({860, 440});
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(split, 1);

    connect(m_moduleFilter, &QComboBox::currentIndexChanged, this,
            &InspectorView::applyFilterFromControls);
    connect(m_protocolFilter, &QComboBox::currentIndexChanged, this,
            &InspectorView::applyFilterFromControls);
    connect(m_errorsOnly, &QCheckBox::toggled, this, &InspectorView::applyFilterFromControls);
    connect(m_pause, &QPushButton::toggled, this, [this](bool paused) {
        if (m_log)
            m_log->setPaused(paused);
    });
    connect(m_clear, &QPushButton::clicked, this, [this] {
        if (m_log)
            m_log->clear();
    });
    connect(m_saveCsv, &QPushButton::clicked, this, [this] { saveInteractive(true); });
    connect(m_saveText, &QPushButton::clicked, this, [this] { saveInteractive(false); });
    connect(m_goTo, &QPushButton::clicked, this, &InspectorView::activateParameterOfCurrent);
    connect(m_table, &QTableView::doubleClicked, this, &InspectorView::activateParameterOfCurrent);
    connect(m_table, &QWidget::customContextMenuRequested, this, &InspectorView::onContextMenu);
    retranslate();
}

InspectorView::~InspectorView() = default;

void InspectorView::setLog(vt::model::TelegramLog *log)
{
    if (m_log == log)
        return;
    if (m_log)
        disconnect(m_log, nullptr, this, nullptr);
    m_table->setModel(nullptr);
    delete m_model;
    m_model = nullptr;
    m_log = log;
    m_detail->clear();
    const bool have = log != nullptr;
    for (QWidget *w : std::initializer_list<QWidget *>{m_pause, m_clear, m_saveCsv, m_saveText})
        w->setEnabled(have);
    if (!log)
        return;
    m_model = new vt::model::TelegramLogModel(log, this);
    m_model->setSummaryOptions(summaryOptions());
    m_table->setModel(m_model);
    applyFilterFromControls();
    // One text line a frame; the summary takes what the short columns leave.
    using Log = vt::model::TelegramLogModel;
    const QFontMetrics metrics = m_table->fontMetrics();
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(metrics.height() + 6);
    const std::pair<int, const char *> widths[] = {
        {Log::TimeColumn, "00000,000000"},      {Log::DirectionColumn, "Direction"},
        {Log::LinkColumn, "sim dma-pn-v51 ×3"}, {Log::ProtocolColumn, "node-image"},
        {Log::ModuleColumn, "Module"},          {Log::StatusColumn, "timeout"}};
    for (const auto &[column, sample] : widths)
        m_table->setColumnWidth(column, metrics.horizontalAdvance(QString::fromUtf8(sample)) + 16);
    m_table->horizontalHeader()->setSectionResizeMode(Log::SummaryColumn, QHeaderView::Stretch);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &InspectorView::onCurrentRowChanged);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &InspectorView::onRowsInserted);
    connect(m_model, &QAbstractItemModel::modelReset, this, &InspectorView::onCurrentRowChanged);
    m_pause->setChecked(log->isPaused());
    connect(log, &vt::model::TelegramLog::pausedChanged, this, [this](bool paused) {
        const QSignalBlocker block(m_pause);
        m_pause->setChecked(paused);
    });
}

void InspectorView::setConnection(vt::model::Connection *connection,
                                  const std::vector<vt::model::ModuleInfo> &modules)
{
    m_connection = connection;
    m_modules = modules;
    rebuildModuleFilter();
    if (m_model)
        m_model->setSummaryOptions(summaryOptions());
    const vt::dev::Dictionary *dict = modules.empty() ? nullptr : modules.front().dictionary;
    m_decode->setDictionary(dict);
    m_decode->setFamily(familyFor(modules.empty() ? -1 : modules.front().address));
    m_compose->setFamily(familyFor(modules.empty() ? -1 : modules.front().address));
    m_compose->setConnection(connection, modules);
    onCurrentRowChanged();
}

void InspectorView::clearConnection()
{
    m_connection = nullptr;
    m_modules.clear();
    rebuildModuleFilter();
    if (m_model)
        m_model->setSummaryOptions(summaryOptions());
    m_decode->setDictionary(nullptr);
    m_compose->clearConnection();
    onCurrentRowChanged();
}

const vt::dev::Dictionary *InspectorView::dictionaryFor(int module) const
{
    for (const auto &m : m_modules)
        if (m.address == module && m.dictionary)
            return m.dictionary;
    return m_modules.empty() ? nullptr : m_modules.front().dictionary;
}

vt::dev::hcs::Family InspectorView::familyFor(int module) const
{
    const vt::dev::Dictionary *d = dictionaryFor(module);
    return d && d->family.rfind("opat", 0) == 0 ? vt::dev::hcs::Family::Opat
                                                : vt::dev::hcs::Family::Dma;
}

vt::model::SummaryOptions InspectorView::summaryOptions() const
{
    vt::model::SummaryOptions o;
    o.language = model::textLanguage();
    o.dictionary = dictionaryFor(-1);
    o.family = familyFor(-1);
    const vt::dev::inspect::ImageLayout layout = imageLayout();
    o.dsp408 = layout.dsp408;
    o.registerBytes = layout.registerBytes;
    return o;
}

vt::dev::inspect::ImageLayout InspectorView::imageLayout() const
{
    vt::dev::inspect::ImageLayout layout;
    if (m_connection) {
        layout.dsp408 = m_connection->spec().dsp408.layout;
        layout.registerBytes = m_connection->spec().dsp408.gateway.byteOrder;
    }
    return layout;
}

void InspectorView::rebuildModuleFilter()
{
    const int current = m_moduleFilter->currentData().toInt();
    const QSignalBlocker block(m_moduleFilter);
    while (m_moduleFilter->count() > 1)
        m_moduleFilter->removeItem(1);
    for (const auto &m : m_modules) {
        QString name = QString::number(m.address);
        if (m.dictionary)
            name += QStringLiteral(" (%1)").arg(QString::fromStdString(m.dictionary->family));
        m_moduleFilter->addItem(name, m.address);
    }
    const int index = m_moduleFilter->findData(current);
    m_moduleFilter->setCurrentIndex(index >= 0 ? index : 0);
    if (index < 0)
        applyFilterFromControls();
}

void InspectorView::applyFilterFromControls()
{
    if (m_syncing || !m_model)
        return;
    vt::model::TelegramFilter f;
    f.module = m_moduleFilter->currentData().toInt();
    f.protocol = m_protocolFilter->currentData().toString();
    f.errorsOnly = m_errorsOnly->isChecked();
    if (!(f == m_model->filter()))
        m_model->setFilter(f);
}

void InspectorView::syncControlsToFilter(const vt::model::TelegramFilter &f)
{
    m_syncing = true;
    int m = m_moduleFilter->findData(f.module);
    if (m < 0) { // a module the connection does not list: offer it anyway
        m_moduleFilter->addItem(QString::number(f.module), f.module);
        m = m_moduleFilter->count() - 1;
    }
    m_moduleFilter->setCurrentIndex(m);
    int p = m_protocolFilter->findData(f.protocol);
    if (p < 0) {
        m_protocolFilter->addItem(f.protocol, f.protocol);
        p = m_protocolFilter->count() - 1;
    }
    m_protocolFilter->setCurrentIndex(p);
    m_errorsOnly->setChecked(f.errorsOnly);
    m_syncing = false;
}

void InspectorView::setFilter(const vt::model::TelegramFilter &filter)
{
    syncControlsToFilter(filter);
    if (m_model && !(m_model->filter() == filter))
        m_model->setFilter(filter);
}

vt::model::TelegramFilter InspectorView::filter() const
{
    return m_model ? m_model->filter() : vt::model::TelegramFilter{};
}

QList<quint64> InspectorView::selectedSeqs() const
{
    QList<quint64> out;
    if (!m_model)
        return out;
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    for (const QModelIndex &i : rows)
        out << m_model->seqAt(i.row());
    std::sort(out.begin(), out.end());
    return out;
}

QStringList InspectorView::parametersOfCurrent() const
{
    if (!m_model || !m_log)
        return {};
    const QModelIndex current = m_table->currentIndex();
    const vt::model::TelegramRecord *r =
        current.isValid() ? m_model->recordAt(current.row()) : nullptr;
    if (!r)
        return {};
    const vt::dev::Dictionary *dict = dictionaryFor(r->module);
    if (!dict)
        return {};
    return vt::model::parametersOfRecord(*m_log, r->seq, *dict, familyFor(r->module),
                                         imageLayout());
}

bool InspectorView::activateParameterOfCurrent()
{
    const QStringList names = parametersOfCurrent();
    const vt::model::TelegramRecord *r = m_model && m_table->currentIndex().isValid()
                                             ? m_model->recordAt(m_table->currentIndex().row())
                                             : nullptr;
    if (names.isEmpty() || !r)
        return false;
    emit parameterActivated(r->module, names.front());
    return true;
}

void InspectorView::showFramesFor(int module, const QString &parameterName)
{
    if (!m_log || !m_model)
        return;
    const vt::dev::Dictionary *dict = dictionaryFor(module);
    if (!dict)
        return;
    const QList<quint64> seqs = vt::model::lastFramesFor(*m_log, module, parameterName, *dict,
                                                         familyFor(module), imageLayout());
    m_table->clearSelection();
    if (seqs.isEmpty())
        return;
    bool hidden = false;
    for (quint64 s : seqs)
        hidden = hidden || m_model->rowOfSeq(s) < 0;
    if (hidden) { // the frames must be visible to be shown: show the module's frames
        vt::model::TelegramFilter f;
        f.module = module;
        setFilter(f);
    }
    QItemSelection selection;
    int firstRow = -1;
    for (quint64 s : seqs) {
        const int row = m_model->rowOfSeq(s);
        if (row < 0)
            continue;
        if (firstRow < 0)
            firstRow = row;
        selection.select(m_model->index(row, 0), m_model->index(row, m_model->columnCount() - 1));
    }
    if (firstRow < 0)
        return;
    m_table->selectionModel()->setCurrentIndex(m_model->index(firstRow, 0),
                                               QItemSelectionModel::NoUpdate);
    m_table->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
    m_table->scrollTo(m_model->index(firstRow, 0));
    m_tabs->setCurrentWidget(m_detail);
    onCurrentRowChanged();
}

void InspectorView::onCurrentRowChanged()
{
    const QModelIndex current = m_model ? m_table->currentIndex() : QModelIndex();
    const vt::model::TelegramRecord *r =
        current.isValid() ? m_model->recordAt(current.row()) : nullptr;
    m_goTo->setEnabled(!parametersOfCurrent().isEmpty());
    if (!r) {
        m_detail->clear();
        return;
    }
    if (r->status == vt::model::TelegramRecord::Status::Timeout || r->bytes.isEmpty()) {
        m_detail->setUndescribed(r->bytes, vt::model::TelegramLog::summary(*r, summaryOptions()));
        return;
    }
    vt::dev::AnyOptions o;
    o.family = familyFor(r->module);
    o.direction = r->direction;
    o.dictionary = dictionaryFor(r->module);
    // The ED1's frames as the link lays them out (--register-bytes, --pzd-words, --ind-byte).
    const vt::dev::inspect::ImageLayout layout = imageLayout();
    o.dsp408 = layout.dsp408;
    o.registerBytes = layout.registerBytes;
    // An answer to a block read names its words after the request's first ID.
    std::optional<std::uint16_t> firstId;
    if (r->direction == vt::dev::Direction::Response && m_log) {
        const auto request = vt::model::requestSeqOf(*m_log, r->seq);
        const vt::model::TelegramRecord *q = request ? m_log->find(*request) : nullptr;
        if (q && q->protocol == r->protocol && r->linkProtocol()) {
            const auto carried = vt::dev::inspect::carriedBy(
                *r->linkProtocol(), vt::link::byteSpan(q->bytes), q->direction, o.family, layout);
            if (!carried.ids.empty())
                firstId = carried.ids.front();
        }
    }
    const auto link = r->linkProtocol();
    const auto d =
        link ? vt::dev::inspect::describeLogged(*link, vt::link::byteSpan(r->bytes), o, firstId)
             : vt::dev::Result<vt::dev::Description, std::string>("no description for protocol '" +
                                                                  r->protocol.toStdString() + "'");
    if (d)
        m_detail->setFrame(r->bytes, *d);
    else
        m_detail->setUndescribed(r->bytes, QString::fromStdString(d.error()));
}

void InspectorView::onRowsInserted()
{
    // Follow the newest frame unless the user scrolled up to read an older one.
    QScrollBar *bar = m_table->verticalScrollBar();
    if (bar->value() >= bar->maximum() - 2 * m_table->verticalHeader()->defaultSectionSize())
        m_table->scrollToBottom();
}

void InspectorView::onContextMenu(const QPoint &pos)
{
    const QModelIndex index = m_table->indexAt(pos);
    if (!index.isValid())
        return;
    m_table->setCurrentIndex(index);
    const QStringList names = parametersOfCurrent();
    const vt::model::TelegramRecord *r = m_model->recordAt(index.row());
    if (!r)
        return;
    QMenu menu(this);
    for (const QString &name : names) {
        const int module = r->module;
        menu.addAction(tr("Go to parameter %1").arg(name), this,
                       [this, module, name] { emit parameterActivated(module, name); });
    }
    QAction *copy = menu.addAction(tr("Decode a copy"));
    connect(copy, &QAction::triggered, this,
            [this, bytes = r->bytes, link = r->linkProtocol(), direction = r->direction] {
                m_decode->setProtocol(link ? std::optional(vt::dev::frameFormatOf(*link))
                                           : std::nullopt);
                m_decode->setDirection(direction);
                m_decode->setText(vt::model::TelegramLog::hexText(bytes));
                m_tabs->setCurrentWidget(m_decode);
            });
    menu.exec(m_table->viewport()->mapToGlobal(pos));
}

namespace {

bool openForWriting(QFile &file, QString *error)
{
    if (file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return true;
    if (error)
        *error = file.errorString();
    return false;
}

} // namespace

bool InspectorView::saveCsv(const QString &path, QString *error) const
{
    QFile file(path);
    return m_log && openForWriting(file, error) &&
           m_log->writeCsv(file, summaryOptions(), filter(), error);
}

bool InspectorView::saveText(const QString &path, QString *error) const
{
    QFile file(path);
    return m_log && openForWriting(file, error) &&
           m_log->writeText(file, summaryOptions(), filter(), error);
}

void InspectorView::saveInteractive(bool csv)
{
    const QString path = QFileDialog::getSaveFileName(
        this, csv ? tr("Save telegrams as CSV") : tr("Save telegrams as text"), QString(),
        csv ? tr("CSV files (*.csv)") : tr("Text files (*.txt)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!(csv ? saveCsv(path, &error) : saveText(path, &error)))
        QMessageBox::warning(this, tr("Save failed"), tr("Could not save %1: %2").arg(path, error));
}

void InspectorView::retranslate()
{
    m_moduleLabel->setText(tr("Module:"));
    m_moduleFilter->setItemText(0, tr("all"));
    m_protocolLabel->setText(tr("Protocol:"));
    m_protocolFilter->setItemText(0, tr("all"));
    m_errorsOnly->setText(tr("Errors only"));
    m_pause->setText(tr("Pause"));
    m_pause->setToolTip(tr("Freezes the list; frames are still recorded and appear when resumed."));
    m_clear->setText(tr("Clear"));
    m_saveCsv->setText(tr("Save CSV…"));
    m_saveText->setText(tr("Save text…"));
    m_goTo->setText(tr("Go to parameter"));
    m_tabs->setTabText(0, tr("Frame"));
    m_tabs->setTabText(1, tr("Decode"));
    m_tabs->setTabText(2, tr("Compose"));
    if (m_model)
        m_model->setSummaryOptions(summaryOptions());
    onCurrentRowChanged();
}

void InspectorView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace vt::ui
