// valvetune: the GUI. Parses the command line, picks the language (command line, then the
// remembered choice, then the system locale), shows the main window and connects when asked to
// (--simulate, --connect).
#include "app/gui/app_settings.h"
#include "app/gui/gui_options.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/startup.h"
#include "model/assert_handler.h"
#include "model/audit/audit_log.h"

#include <QApplication>
#include <QGuiApplication>
#include <QIcon>
#include <QMessageBox>
#include <cstdio>
#ifdef __GLIBC__
#include <malloc.h>
#endif

int main(int argc, char *argv[])
{
#ifdef __GLIBC__
    // Large buffers (the monitor's sample rings, the telegram log's ring) get their own mappings,
    // returned to the system when freed. With glibc's default, the threshold rises after the
    // first such free, later rings land in the heap, and the holes they leave when the channels
    // change are touched page by page for the rest of the run: resident memory creeps (issue #21,
    // docs/PERFORMANCE.md "GUI resident memory over 30 minutes").
    mallopt(M_MMAP_THRESHOLD, 1024 * 1024);
#endif
    // The command line first, without a display: --help, --version and a wrong option answer on a
    // terminal and a server alike.
    QString help;
    vt::app::GuiOptions options;
    {
        QCoreApplication probe(argc, argv);
        options = vt::app::parseGuiOptions(QCoreApplication::arguments(), &help);
    }
    if (options.exitNow) {
        if (options.exitCode == -1) {
            std::fputs(qPrintable(help), stdout);
            return 0;
        }
        if (options.exitCode == -2) {
            std::printf("valvetune %s\n", VT_VERSION);
            return 0;
        }
        std::fprintf(stderr, "valvetune: %s\n", qPrintable(options.error));
        // Started from a desktop shortcut nobody reads stderr: say it where it is seen.
        if (vt::app::displayAvailable()) {
            QApplication app(argc, argv);
            vt::app::Language language;
            language.setLanguage(vt::app::Language::isKnown(options.language)
                                     ? options.language
                                     : vt::app::Language::systemDefault());
            vt::app::startupErrorBox(options.error)->exec();
        }
        return options.exitCode;
    }

    QApplication app(argc, argv);
    vt::model::installQtAssertHandler();
    QCoreApplication::setOrganizationName(QStringLiteral("ValveTune"));
    QCoreApplication::setApplicationName(QStringLiteral("ValveTune"));
    QCoreApplication::setApplicationVersion(QStringLiteral(VT_VERSION));
    // The installed desktop entry and icon carry the application id: window managers and Wayland
    // compositors match the window to them through it.
    QGuiApplication::setDesktopFileName(QStringLiteral(VT_APP_ID));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral(VT_APP_ID)));

    vt::app::AppSettings settings;
    vt::app::Language language;
    QString code = options.language;
    if (code.isEmpty())
        code = settings.language();
    if (!vt::app::Language::isKnown(code))
        code = vt::app::Language::systemDefault();
    language.setLanguage(code);

    // Every write of this session goes into one log file (model/audit), kept after a crash.
    vt::model::AuditLog audit(QStringLiteral("valvetune"), QStringLiteral(VT_VERSION),
                              options.auditDir);
    const vt::model::AuditLog::Scope auditScope(audit);

    vt::app::MainWindow window(settings, language);
    window.show();
    vt::app::startFromOptions(window, options);
    return QApplication::exec();
}
