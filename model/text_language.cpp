#include "text_language.h"

#include <QLocale>

namespace vt::model {

dev::Language textLanguage()
{
    return QLocale().language() == QLocale::German ? dev::Language::German : dev::Language::English;
}

QString localText(const dev::LocalText &text)
{
    return QString::fromStdString(text.in(textLanguage()));
}

} // namespace vt::model
