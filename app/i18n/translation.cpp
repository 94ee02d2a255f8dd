#include "translation.h"

#include <QCoreApplication>
#include <QLibraryInfo>

namespace vt::i18n {

std::unique_ptr<Translation> Translation::load(const QString &code)
{
    std::unique_ptr<Translation> t(new Translation(code));
    // valvetune_en.qm carries only plural forms; English source texts are the fallback.
    if (!t->m_app.load(QStringLiteral(":/i18n/valvetune_%1.qm").arg(code)))
        return nullptr;
    // Qt's own dialogs ("Cancel", "&Yes"): optional, present when qt6-translations-l10n is.
    t->m_haveQt = t->m_qt.load(QStringLiteral("qtbase_%1").arg(code),
                               QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    return t;
}

Translation::~Translation()
{
    if (!m_installed)
        return;
    QCoreApplication::removeTranslator(&m_app);
    if (m_haveQt)
        QCoreApplication::removeTranslator(&m_qt);
}

void Translation::install()
{
    if (m_installed)
        return;
    // The last installed is asked first: ValveTune's words before Qt's.
    if (m_haveQt)
        QCoreApplication::installTranslator(&m_qt);
    QCoreApplication::installTranslator(&m_app);
    m_installed = true;
}

} // namespace vt::i18n
