// The inspector's choice between the {en, de} texts of the Qt-free core: the app's Language sets
// the default QLocale, so the current QLocale decides (re-read on every LanguageChange).
#pragma once

#include "core/local_text.h"

#include <QLocale>
#include <QString>

namespace vt::ui {

inline vt::dev::Language coreLanguage()
{
    return QLocale().language() == QLocale::German ? vt::dev::Language::German
                                                   : vt::dev::Language::English;
}

inline QString localText(const vt::dev::LocalText &text)
{
    return QString::fromStdString(text.in(coreLanguage()));
}

} // namespace vt::ui
