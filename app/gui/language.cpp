#include "language.h"

#include <QApplication>
#include <QWidget>

namespace vt::app {

Language::Language(QObject *parent) : QObject(parent)
{
}

Language::~Language() = default;

QString Language::systemDefault()
{
    return QLocale::system().language() == QLocale::German ? QStringLiteral("de")
                                                           : QStringLiteral("en");
}

bool Language::setLanguage(const QString &code)
{
    if (!isKnown(code))
        return false;
    if (code == m_current)
        return true;

    auto next = i18n::Translation::load(code);
    if (!next)
        return false;
    m_translation.reset(); // the old language leaves before the new one comes
    const QLocale locale(code == QLatin1String("de") ? QLocale::German : QLocale::English,
                         code == QLatin1String("de") ? QLocale::Germany : QLocale::UnitedStates);
    QLocale::setDefault(locale);
    // A widget's locale() is a copy of the default taken when the widget was made, and
    // setDefault() does not reach the widgets that exist: a spin box made in English went on
    // reading the German "1,5" with English rules. Every window is told; children inherit it.
    for (QWidget *window : QApplication::topLevelWidgets())
        window->setLocale(locale);
    next->install(); // sends LanguageChange to every widget
    m_translation = std::move(next);
    m_current = code;
    emit languageChanged(code);
    return true;
}

} // namespace vt::app
