// Language: switches the UI language at run time. Installs the embedded ValveTune catalogue
// (and Qt's own, when the system has it; app/i18n/translation.h), sets the default QLocale and the
// locale of every open window, so every widget gets a LanguageChange event and numbers follow
// ("1,000 V" in German). GUI thread only.
#pragma once

#include "app/i18n/translation.h"

#include <QLocale>
#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>

namespace vt::app {

class Language : public QObject
{
    Q_OBJECT
public:
    explicit Language(QObject *parent = nullptr);
    ~Language() override;

    static QStringList available() { return {QStringLiteral("en"), QStringLiteral("de")}; }
    // "de" when the system locale is German, else "en".
    static QString systemDefault();
    static bool isKnown(const QString &code) { return available().contains(code); }

    // Returns false (and changes nothing) for an unknown code or a catalogue that fails to load.
    bool setLanguage(const QString &code);
    QString current() const { return m_current; }

signals:
    void languageChanged(const QString &code);

private:
    QString m_current;
    std::unique_ptr<i18n::Translation> m_translation;
};

} // namespace vt::app
