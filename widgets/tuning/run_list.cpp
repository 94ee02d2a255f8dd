#include "run_list.h"

#include "dict/dictionary_loader.h"

#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace vt::ui {

RunList::RunList(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    layout->addWidget(m_title);
    m_list = new QListWidget(this);
    m_list->setMinimumHeight(60);
    layout->addWidget(m_list, 1);
    auto *files = new QHBoxLayout;
    m_save = new QPushButton(this);
    m_load = new QPushButton(this);
    files->addWidget(m_save);
    files->addWidget(m_load);
    layout->addLayout(files);
    connect(m_save, &QPushButton::clicked, this, &RunList::saveCurrent);
    connect(m_load, &QPushButton::clicked, this, &RunList::loadRuns);
    connect(m_list, &QListWidget::currentRowChanged, this, &RunList::selectionChanged);
    connect(m_list, &QListWidget::itemChanged, this, &RunList::selectionChanged);
    retranslate();
    setFilesEnabled(true);
}

RunList::~RunList() = default;

void RunList::addRun(std::unique_ptr<model::TuningRun> run, bool tickPrevious)
{
    m_nextNumber = std::max(m_nextNumber, run->number + 1);
    auto *item = new QListWidgetItem(model::runTitle(*run));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Unchecked);
    m_runs.push_back(std::move(run));
    {
        const QSignalBlocker block(m_list);
        m_list->addItem(item);
        m_list->setCurrentItem(item);
        if (tickPrevious && m_list->count() >= 2)
            m_list->item(m_list->count() - 2)->setCheckState(Qt::Checked);
    }
    m_save->setEnabled(m_load->isEnabled());
    emit selectionChanged();
}

std::vector<const model::TuningRun *> RunList::shownRuns() const
{
    std::vector<const model::TuningRun *> out;
    const int current = m_list->currentRow();
    if (current < 0 || current >= static_cast<int>(m_runs.size()))
        return out;
    out.push_back(m_runs[static_cast<std::size_t>(current)].get());
    for (int i = 0; i < m_list->count(); ++i)
        if (i != current && m_list->item(i)->checkState() == Qt::Checked)
            out.push_back(m_runs[static_cast<std::size_t>(i)].get());
    return out;
}

void RunList::setFilesEnabled(bool enabled)
{
    m_load->setEnabled(enabled);
    m_save->setEnabled(enabled && m_list->currentRow() >= 0);
}

void RunList::saveCurrent()
{
    const auto runs = shownRuns();
    if (runs.empty())
        return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Run"),
                                                      tr("run-%1.csv").arg(runs.front()->number),
                                                      tr("Run recordings (*.csv)"));
    if (path.isEmpty())
        return;
    const QString error = model::saveRun(*runs.front(), path);
    emit statusMessage(error.isEmpty() ? tr("Saved %1 and its .json.").arg(path) : error);
}

void RunList::loadRuns()
{
    const QStringList paths =
        QFileDialog::getOpenFileNames(this, tr("Load Runs"), QString(), tr("Runs (*.json *.csv)"));
    QStringList problems;
    for (const QString &path : paths) {
        QString why;
        auto run = model::loadRun(path, *dev::builtinDictionaries(), &why);
        if (!run) {
            problems << why;
            continue;
        }
        addRun(std::make_unique<model::TuningRun>(std::move(*run)));
    }
    if (!problems.isEmpty())
        emit statusMessage(problems.join(QLatin1Char('\n')));
}

void RunList::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void RunList::retranslate()
{
    m_title->setText(tr("Runs"));
    m_save->setText(tr("Save Run…"));
    m_load->setText(tr("Load Runs…"));
    m_list->setToolTip(tr("The current run is drawn with its marks; tick others to overlay them "
                          "and to compare their settings."));
    for (int i = 0; i < m_list->count() && i < static_cast<int>(m_runs.size()); ++i)
        m_list->item(i)->setText(model::runTitle(*m_runs[static_cast<std::size_t>(i)]));
}

} // namespace vt::ui
