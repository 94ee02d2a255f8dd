// Reading and writing .vtpar parameter files and their CSV export for the GUI: bounded reads
// (nothing over dev::files::kMaxFileBytes is read into memory) and atomic saves (QSaveFile: the
// old file stays intact until the new one is complete). Errors come back as one translated line.
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "dict/dictionary.h"
#include "files/param_file.h"

#include <QString>
#include <optional>

namespace vt::model {

dev::Result<dev::files::ParamFile, QString> readParamFile(const QString &path, dev::Language lang);
// nullopt on success, else why the file was not written (the old file is unchanged).
std::optional<QString> saveParamFile(const QString &path, const dev::files::ParamFile &file,
                                     const dev::DictionarySet &dictionaries, dev::Language lang);
// Every module of the file, one CSV block per module, in the language's separator and decimal sign.
std::optional<QString> exportParamCsv(const QString &path, const dev::files::ParamFile &file,
                                      const dev::DictionarySet &dictionaries, dev::Language lang);

} // namespace vt::model
