// AppSettings: what the GUI remembers between runs (window layout, language, recent files),
// over QSettings. Tests pass their own QSettings (an INI file in a temporary folder).
// GUI thread only.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <memory>

class QSettings;

namespace vt::app {

class AppSettings
{
public:
    // The user's settings (organisation "ValveTune", application "ValveTune").
    AppSettings();
    // Settings in a given INI file (tests, portable installs).
    explicit AppSettings(const QString &iniPath);
    ~AppSettings();

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray &geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray &state);

    // "en" or "de"; empty when the user never chose (first start follows the system locale).
    QString language() const;
    void setLanguage(const QString &language);

    QStringList recentFiles() const;
    void setRecentFiles(const QStringList &files);

    void sync();
    // The underlying store, for widgets that remember their own group (connect dialog).
    QSettings &store() { return *m_settings; }

private:
    std::unique_ptr<QSettings> m_settings;
};

} // namespace vt::app
