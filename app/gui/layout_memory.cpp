#include "layout_memory.h"

#include <QAbstractItemView>
#include <QEvent>
#include <QHeaderView>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QTreeView>
#include <utility>

namespace vt::app {
namespace {

const QString kGroup = QStringLiteral("viewLayout");

QHeaderView *headerOf(QAbstractItemView *view)
{
    if (auto *tree = qobject_cast<QTreeView *>(view))
        return tree->header();
    if (auto *table = qobject_cast<QTableView *>(view))
        return table->horizontalHeader();
    return nullptr;
}

// Restores a splitter once it is shown at its own size: restored while hidden (the editor behind
// the welcome page), its sizes would be scaled to the hidden size and stay small.
class RestoreWhenShown : public QObject
{
public:
    RestoreWhenShown(QSplitter *splitter, QByteArray state)
        : QObject(splitter), m_splitter(splitter), m_state(std::move(state))
    {
        splitter->installEventFilter(this);
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        const bool sized = event->type() == QEvent::Show || event->type() == QEvent::Resize;
        if (watched == m_splitter && sized && m_splitter->isVisible()) {
            m_splitter->removeEventFilter(this);
            m_splitter->restoreState(m_state);
            deleteLater();
        }
        return false;
    }

private:
    QSplitter *m_splitter;
    QByteArray m_state;
};

} // namespace

void saveViewLayout(const QWidget &root, QSettings &store)
{
    store.beginGroup(kGroup);
    for (QSplitter *s : root.findChildren<QSplitter *>()) {
        if (!s->objectName().isEmpty())
            store.setValue(QStringLiteral("splitter/") + s->objectName(), s->saveState());
    }
    for (QAbstractItemView *v : root.findChildren<QAbstractItemView *>()) {
        QHeaderView *header = headerOf(v);
        if (v->objectName().isEmpty() || !header)
            continue;
        // Widths only: which columns show follows what the view holds (device, file).
        QVariantList widths;
        for (int i = 0; i < header->count(); ++i)
            widths << (header->isSectionHidden(i) ? 0 : header->sectionSize(i));
        store.setValue(QStringLiteral("columns/") + v->objectName(), widths);
    }
    store.endGroup();
}

void restoreViewLayout(QWidget &root, QSettings &store)
{
    store.beginGroup(kGroup);
    for (QSplitter *s : root.findChildren<QSplitter *>()) {
        const QByteArray state =
            store.value(QStringLiteral("splitter/") + s->objectName()).toByteArray();
        if (s->objectName().isEmpty() || state.isEmpty())
            continue;
        if (s->isVisible())
            s->restoreState(state);
        else
            new RestoreWhenShown(s, state);
    }
    for (QAbstractItemView *v : root.findChildren<QAbstractItemView *>()) {
        QHeaderView *header = headerOf(v);
        if (v->objectName().isEmpty() || !header)
            continue;
        const QVariantList widths =
            store.value(QStringLiteral("columns/") + v->objectName()).toList();
        // A stretched or content-sized column keeps sizing itself.
        for (int i = 0; i < qMin(widths.size(), header->count()); ++i)
            if (const int w = widths[i].toInt();
                w > 0 && header->sectionResizeMode(i) == QHeaderView::Interactive)
                header->resizeSection(i, w);
    }
    store.endGroup();
}

} // namespace vt::app
