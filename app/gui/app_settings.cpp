#include "app_settings.h"

#include <QSettings>

namespace vt::app {
namespace {
const char kGeometry[] = "window/geometry";
const char kState[] = "window/state";
const char kLanguage[] = "ui/language";
const char kRecent[] = "files/recent";
} // namespace

AppSettings::AppSettings() : m_settings(std::make_unique<QSettings>("ValveTune", "ValveTune"))
{
}

AppSettings::AppSettings(const QString &iniPath)
    : m_settings(std::make_unique<QSettings>(iniPath, QSettings::IniFormat))
{
}

AppSettings::~AppSettings() = default;

QByteArray AppSettings::windowGeometry() const
{
    return m_settings->value(kGeometry).toByteArray();
}
void AppSettings::setWindowGeometry(const QByteArray &geometry)
{
    m_settings->setValue(kGeometry, geometry);
}
QByteArray AppSettings::windowState() const
{
    return m_settings->value(kState).toByteArray();
}
void AppSettings::setWindowState(const QByteArray &state)
{
    m_settings->setValue(kState, state);
}
QString AppSettings::language() const
{
    return m_settings->value(kLanguage).toString();
}
void AppSettings::setLanguage(const QString &language)
{
    m_settings->setValue(kLanguage, language);
}
QStringList AppSettings::recentFiles() const
{
    return m_settings->value(kRecent).toStringList();
}
void AppSettings::setRecentFiles(const QStringList &files)
{
    m_settings->setValue(kRecent, files);
}
void AppSettings::sync()
{
    m_settings->sync();
}

} // namespace vt::app
