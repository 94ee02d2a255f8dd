#include "startup.h"

#include "device_controller.h"
#include "file_controller.h"
#include "gui_options.h"
#include "main_window.h"
#include "model/session/sim_endpoint.h"

#include <QMessageBox>
#include <QStringList>

namespace vt::app {

void startFromOptions(MainWindow &window, const GuiOptions &options)
{
    if (!options.openFile.isEmpty())
        window.files().openPath(options.openFile);
    if (!options.simulate.isEmpty()) {
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim = *model::parseSimSpec(options.simulate); // checked by parseGuiOptions
        spec.sim.factory = options.factory;
        window.device().connectTo(spec);
    }
    if (options.connection)
        window.device().connectTo(*options.connection);
}

bool displayAvailable()
{
    const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
    if (platform.startsWith(QLatin1String("offscreen")) ||
        platform.startsWith(QLatin1String("minimal")))
        return false;
    return !qEnvironmentVariableIsEmpty("DISPLAY") ||
           !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
}

QMessageBox *startupErrorBox(const QString &error)
{
    auto *box = new QMessageBox(QMessageBox::Critical, QStringLiteral("ValveTune"),
                                QObject::tr("ValveTune cannot start with this command line:"),
                                QMessageBox::Close);
    box->setObjectName(QStringLiteral("startupError"));
    // The command line's words stay as typed; "valvetune --help" lists what it takes.
    box->setInformativeText(error + QStringLiteral("\n\n") +
                            QObject::tr("Run \"valvetune --help\" in a terminal for the options."));
    box->setAttribute(Qt::WA_DeleteOnClose);
    return box;
}

} // namespace vt::app
