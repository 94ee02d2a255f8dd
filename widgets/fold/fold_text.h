// Small helpers of the fold wizard pages: the UI language for texts of the Qt-free core
// (dev::LocalText) — German when the default QLocale is German, which app/gui/language.cpp sets
// on every switch — and numbers in the locale's notation.
#pragma once

#include "core/local_text.h"

#include <QLocale>
#include <QString>

namespace vt::ui {

inline dev::Language foldLanguage()
{
    return QLocale().language() == QLocale::German ? dev::Language::German : dev::Language::English;
}

inline QString foldText(const dev::LocalText &text)
{
    return QString::fromStdString(text.in(foldLanguage()));
}

} // namespace vt::ui
