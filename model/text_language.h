// Which of the Qt-free core's {en, de} texts (dev::LocalText) to show: the UI language, which
// app/gui/language.cpp sets as the default QLocale on every switch. One place for every model
// and widget that picks a side (models and widgets re-read it on LanguageChange).
#pragma once

#include "core/local_text.h"

#include <QString>

namespace vt::model {

dev::Language textLanguage();
QString localText(const dev::LocalText &text);

} // namespace vt::model
