#include "param_file_io.h"

#include "files/param_csv.h"
#include "model/file_write.h"

#include <QCoreApplication>
#include <QFile>

namespace vt::model {
namespace {

std::optional<QString> writeAtomically(const QString &path, const std::string &bytes)
{
    QString why = writeFileAtomically(path, bytes);
    return why.isEmpty() ? std::nullopt : std::optional<QString>(std::move(why));
}

QString tooLarge(const QString &path)
{
    return QCoreApplication::translate("vt::model::ParamFileIo",
                                       "%1 is larger than %2 MiB: not a parameter file.")
        .arg(path)
        .arg(dev::files::kMaxFileBytes / (1024 * 1024));
}

} // namespace

dev::Result<dev::files::ParamFile, QString> readParamFile(const QString &path, dev::Language lang)
{
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return QCoreApplication::translate("vt::model::ParamFileIo", "Cannot open %1: %2")
            .arg(path, in.errorString());
    if (in.size() > static_cast<qint64>(dev::files::kMaxFileBytes))
        return tooLarge(path);
    // Bounded even when size() lies (a pipe, a growing file): one byte more than allowed is enough
    // to know.
    const QByteArray bytes = in.read(static_cast<qint64>(dev::files::kMaxFileBytes) + 1);
    if (bytes.size() > static_cast<qsizetype>(dev::files::kMaxFileBytes))
        return tooLarge(path);
    auto parsed = dev::files::parseParamFile(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (!parsed)
        return QString::fromStdString(parsed.error().text().in(lang));
    return std::move(parsed).value();
}

std::optional<QString> saveParamFile(const QString &path, const dev::files::ParamFile &file,
                                     const dev::DictionarySet &dictionaries, dev::Language lang)
{
    return writeAtomically(path, dev::files::writeParamFile(file, &dictionaries, lang));
}

std::optional<QString> exportParamCsv(const QString &path, const dev::files::ParamFile &file,
                                      const dev::DictionarySet &dictionaries, dev::Language lang)
{
    std::string text;
    dev::files::CsvOptions options;
    options.lang = lang;
    for (std::size_t i = 0; i < file.modules.size(); ++i) {
        const dev::files::ModuleRecord &record = file.modules[i];
        options.byteOrderMark = i == 0;
        if (i > 0)
            text += "\r\n";
        text += dev::files::exportCsv(record, dictionaries.find(record.family), options);
    }
    return writeAtomically(path, text);
}

} // namespace vt::model
