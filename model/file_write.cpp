#include "model/file_write.h"

#include <QCoreApplication>
#include <QSaveFile>

namespace vt::model {

QString writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    QSaveFile out(path);
    if (out.open(QIODevice::WriteOnly) && out.write(bytes) == bytes.size() && out.commit())
        return {};
    const QString why = out.errorString();
    out.cancelWriting();
    return QCoreApplication::translate("vt::model::ParamFileIo", "Cannot write %1: %2")
        .arg(path, why);
}

QString writeFileAtomically(const QString &path, const std::string &bytes)
{
    return writeFileAtomically(
        path, QByteArray::fromRawData(bytes.data(), static_cast<qsizetype>(bytes.size())));
}

} // namespace vt::model
