#include "language.h"

#include <QApplication>
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>
#include <QWidget>

namespace vt::app {

Language::Language(QObject *parent) : QObject(parent)
{
}

Language::~Language()
{
    if (m_app)
        QCoreApplication::removeTranslator(m_app.get());
    if (m_qt)
        QCoreApplication::removeTranslator(m_qt.get());
}

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

    auto app = std::make_unique<QTranslator>();
    // valvetune_en.qm carries only plural forms; English source texts are the fallback.
    if (!app->load(QStringLiteral(":/i18n/valvetune_%1.qm").arg(code)))
        return false;
    // Qt's own dialogs ("Cancel", "&Yes"): optional, present when qt6-translations-l10n is.
    auto qt = std::make_unique<QTranslator>();
    const bool haveQt = qt->load(QStringLiteral("qtbase_%1").arg(code),
                                 QLibraryInfo::path(QLibraryInfo::TranslationsPath));

    if (m_app)
        QCoreApplication::removeTranslator(m_app.get());
    if (m_qt)
        QCoreApplication::removeTranslator(m_qt.get());
    m_app = std::move(app);
    m_qt = haveQt ? std::move(qt) : nullptr;
    const QLocale locale(code == QLatin1String("de") ? QLocale::German : QLocale::English,
                         code == QLatin1String("de") ? QLocale::Germany : QLocale::UnitedStates);
    QLocale::setDefault(locale);
    // A widget's locale() is a copy of the default taken when the widget was made, and
    // setDefault() does not reach the widgets that exist: a spin box made in English went on
    // reading the German "1,5" with English rules. Every window is told; children inherit it.
    for (QWidget *window : QApplication::topLevelWidgets())
        window->setLocale(locale);
    if (m_qt)
        QCoreApplication::installTranslator(m_qt.get());
    QCoreApplication::installTranslator(m_app.get()); // sends LanguageChange to every widget
    m_current = code;
    emit languageChanged(code);
    return true;
}

} // namespace vt::app
