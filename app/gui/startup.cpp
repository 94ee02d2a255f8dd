#include "startup.h"

#include "device_controller.h"
#include "file_controller.h"
#include "gui_options.h"
#include "main_window.h"
#include "model/session/sim_endpoint.h"

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

} // namespace vt::app
