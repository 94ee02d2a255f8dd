// writeFileAtomically(): the one way the model layer writes a file a person saved (parameter
// files, run files, reference fingerprints, report HTML/JSON) — through QSaveFile, so a failed
// write never leaves half a file in place of the old one. GUI or any thread, one file at a time.
#pragma once

#include <QByteArray>
#include <QString>
#include <string>

namespace vt::model {

// Empty on success, else why not, for people ("Cannot write PATH: reason").
QString writeFileAtomically(const QString &path, const QByteArray &bytes);
QString writeFileAtomically(const QString &path, const std::string &bytes);

} // namespace vt::model
