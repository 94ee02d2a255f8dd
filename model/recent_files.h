// RecentFiles: the bounded, most-recent-first list behind File ▸ Recent. Pure data (no widgets,
// no QSettings); the app loads and stores it. GUI thread only.
#pragma once

#include <QObject>
#include <QStringList>

namespace vt::model {

class RecentFiles : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultLimit = 10;

    explicit RecentFiles(int limit = kDefaultLimit, QObject *parent = nullptr);

    // Moves (or adds) the file to the front; paths are compared after cleaning.
    void add(const QString &path);
    void remove(const QString &path);
    void clear();
    void setFiles(const QStringList &files);

    QStringList files() const { return m_files; }
    int limit() const { return m_limit; }

signals:
    void changed();

private:
    QStringList m_files;
    int m_limit;
};

} // namespace vt::model
