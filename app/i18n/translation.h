// Translation: ValveTune's embedded catalogue of one language (:/i18n/valvetune_<code>.qm, built
// from translations/*.ts) and Qt's own when the system has it, in force for the whole program
// while the object is installed. valvetune's Language and valvetune-cli's --lang both go through
// it. Owner: whoever switches the language; the thread of the QCoreApplication.
#pragma once

#include <QString>
#include <QTranslator>
#include <memory>

namespace vt::i18n {

class Translation
{
public:
    // The catalogues of `code` ("en": plural forms only, "de"); nullptr when ValveTune has no
    // catalogue for it.
    static std::unique_ptr<Translation> load(const QString &code);
    ~Translation(); // uninstalls, so a language never outlives its owner
    Translation(const Translation &) = delete;
    Translation &operator=(const Translation &) = delete;

    // Puts the catalogues in force (every widget gets a LanguageChange event).
    void install();
    QString code() const { return m_code; }

private:
    explicit Translation(const QString &code) : m_code(code) {}

    QString m_code;
    QTranslator m_app;
    QTranslator m_qt;
    bool m_haveQt = false;
    bool m_installed = false;
};

} // namespace vt::i18n
