#include "recent_files.h"

#include <QDir>

namespace vt::model {

RecentFiles::RecentFiles(int limit, QObject *parent) : QObject(parent), m_limit(qMax(1, limit))
{
}

void RecentFiles::add(const QString &path)
{
    const QString clean = QDir::cleanPath(path);
    if (clean.isEmpty())
        return;
    m_files.removeAll(clean);
    m_files.prepend(clean);
    while (m_files.size() > m_limit)
        m_files.removeLast();
    emit changed();
}

void RecentFiles::remove(const QString &path)
{
    if (m_files.removeAll(QDir::cleanPath(path)) > 0)
        emit changed();
}

void RecentFiles::clear()
{
    if (m_files.isEmpty())
        return;
    m_files.clear();
    emit changed();
}

void RecentFiles::setFiles(const QStringList &files)
{
    m_files.clear();
    for (const QString &f : files) {
        const QString clean = QDir::cleanPath(f);
        if (!clean.isEmpty() && !m_files.contains(clean) && m_files.size() < m_limit)
            m_files.append(clean);
    }
    emit changed();
}

} // namespace vt::model
