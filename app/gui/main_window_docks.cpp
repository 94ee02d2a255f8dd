// MainWindow's docks: the node view, the monitor, the workbench, the telegrams and the
// linearisation, and how they are wired to each other and to the workspace (main_window.h).
#include "device_controller.h"
#include "device_state_control.h"
#include "main_window.h"
#include "model/curve/lcurve_table_model.h"
#include "model/params/curve_binding.h"
#include "widgets/curve/lcurve_editor.h"
#include "widgets/editor/node_view.h"
#include "widgets/editor/parameter_editor.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/inspector_view.h"
#include "widgets/monitor/monitor_view.h"
#include "widgets/tuning/workbench_view.h"
#include "workspace.h"

#include <QDockWidget>
#include <QMenu>

namespace vt::app {

void MainWindow::createDocks()
{
    auto dock = [this](const char *name, QWidget *content, Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(this);
        d->setObjectName(QString::fromLatin1(name));
        content->setParent(d);
        d->setWidget(content);
        addDockWidget(area, d);
        m_viewMenu->addAction(d->toggleViewAction());
        return d;
    };
    m_nodeView = new ui::NodeView(m_workspace->document(), this);
    m_nodeDock = dock("dockNode", m_nodeView, Qt::LeftDockWidgetArea);
    // The live plot of desired / actual value and solenoid currents, with the tuning journal.
    m_monitor = new ui::MonitorView(this);
    m_monitorDock = dock("dockMonitor", m_monitor, Qt::BottomDockWidgetArea);
    connect(m_monitor, &ui::MonitorView::statusMessage, this, &MainWindow::showStatus);
    connect(m_device, &DeviceController::written, m_monitor, &ui::MonitorView::journalWrites);
    // The ED1/SD1's device state machine, from the node view's context menu.
    auto *state = new DeviceStateControl(*m_workspace, this);
    connect(m_nodeView, &ui::NodeView::controlWordRequested, state, &DeviceStateControl::request);
    connect(m_nodeView, &ui::NodeView::resetFaultRequested, state, &DeviceStateControl::resetFault);
    connect(m_nodeView, &ui::NodeView::valueRequested, state, &DeviceStateControl::requestValue);
    connect(state, &DeviceStateControl::written, m_monitor, &ui::MonitorView::journalWrites);
    connect(state, &DeviceStateControl::statusMessage, this, &MainWindow::showStatus);
    // Every frame in and out of the connection (Workspace's TelegramRecorder fills the log).
    m_inspector = new ui::InspectorView(this);
    m_inspector->setLog(&m_workspace->telegramLog());
    m_telegramsDock = dock("dockTelegrams", m_inspector, Qt::BottomDockWidgetArea);
    connect(m_editor, &ui::ParameterEditor::showFramesRequested, this,
            [this](int module, const QString &name) {
                m_telegramsDock->show();
                m_telegramsDock->raise();
                m_inspector->showFramesFor(m_workspace->document().module(module).address, name);
            });
    // Stopping the monitor ends a test: the set values the tool changed are offered back.
    connect(m_monitor, &ui::MonitorView::stoppedByUser, this,
            [this] { m_device->offerRestore(tr("The monitor was stopped:"), [] {}); });
    // A write sent from Compose reaches the tuning journal as every other write does.
    connect(m_inspector->composePanel(), &ui::ComposePanel::wrote, m_monitor,
            &ui::MonitorView::journalWrites);
    connect(m_inspector, &ui::InspectorView::parameterActivated, this,
            [this](int address, const QString &name) {
                const int module = m_workspace->document().findModule(address);
                if (module < 0)
                    return;
                const dev::Dictionary *dict = m_workspace->document().module(module).dictionary;
                if (const dev::ParamMeta *row = dict->find(name.toStdString()))
                    m_editor->selectParameter(module, row);
            });
    // Linearisation: the L curves of the module the editor works on, dragged or typed.
    m_curves = new model::LCurveTableModel(this);
    m_curveBinding = new model::CurveBinding(m_workspace->document(), *m_curves, this);
    m_curveEditor = new ui::LCurveEditor(this);
    m_curveEditor->setModel(m_curves);
    connect(m_curveBinding, &model::CurveBinding::moduleShown, m_curveEditor,
            &ui::LCurveEditor::setModule);
    m_curveDock = dock("dockCurve", m_curveEditor, Qt::BottomDockWidgetArea);
    // The tuning workbench: test signals on a set value, step and frequency response, runs.
    m_workbench = new ui::WorkbenchView(this);
    // Its column of controls scrolls inside it while Start, Stop and the outcome stay in view,
    // so the docks tabbed with it keep a low bottom area on a 1366 × 768 laptop.
    m_workbenchDock = dock("dockWorkbench", m_workbench, Qt::BottomDockWidgetArea);
    connect(m_workbench, &ui::WorkbenchView::written, m_monitor, &ui::MonitorView::journalWrites);
    connect(m_workbench, &ui::WorkbenchView::statusMessage, this, &MainWindow::showStatus);
    // The editor keeps the full width; monitor, workbench, telegrams and curves share the bottom
    // as tabs.
    tabifyDockWidget(m_monitorDock, m_workbenchDock);
    tabifyDockWidget(m_monitorDock, m_telegramsDock);
    tabifyDockWidget(m_monitorDock, m_curveDock);
    m_monitorDock->raise();
    // Wide enough for a module's lines ("Source of the control word  Control word acting is …").
    resizeDocks({m_nodeDock}, {420}, Qt::Horizontal);
    resizeDocks({m_monitorDock}, {300}, Qt::Vertical);
    connect(m_nodeView, &ui::NodeView::moduleActivated, this, [this](int module) {
        const auto &m = m_workspace->document().module(module);
        if (!m.dictionary->params.empty())
            m_editor->selectParameter(module, &m.dictionary->params.front());
        m_curveBinding->setModule(module);
    });
    connect(m_editor, &ui::ParameterEditor::parameterSelected, this,
            [this](int module, const dev::ParamMeta *row) {
                if (module != m_curveBinding->module())
                    m_curveBinding->setModule(module);
                if (row && row->block == "L")
                    m_curveDock->raise();
            });
}

} // namespace vt::app
