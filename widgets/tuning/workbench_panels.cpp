// WorkbenchView's tabs beside the results: the guided gain change and the reference fingerprint,
// each a panel of its own wired to this view's module, set value, rate, window and journal.
#include "guided_panel.h"
#include "reference_panel.h"
#include "run_list.h"
#include "run_results_tabs.h"
#include "signal_form.h"
#include "widgets/number_box.h"
#include "workbench_view.h"

#include <QCheckBox>
#include <QScrollArea>

namespace vt::ui {

// The guided gain change (guided_panel.h) drives this view's module, set value and step, and
// hands its iterations to the run list (overlaid) and its writes to the journal.
void WorkbenchView::buildGuided()
{
    GuidedHooks hooks;
    hooks.access = [this] { return m_access; };
    hooks.module = [this] { return currentModule(); };
    hooks.setValue = [this] { return currentSetValue(); };
    hooks.signal = [this] { return m_form->spec(); };
    hooks.rateHz = [this] { return m_rate->value(); };
    hooks.window = [this] {
        return m_useWindow->isChecked() ? std::optional<double>(m_window->value()) : std::nullopt;
    };
    hooks.busy = [this] { return isRunning() || referenceActive(); };
    hooks.addRun = [this](std::unique_ptr<model::TuningRun> run, bool overlayPrevious) {
        run->number = m_runs->nextNumber();
        m_runs->addRun(std::move(run), overlayPrevious);
    };
    hooks.written = [this](int module, const std::vector<model::WriteItem> &items) {
        emit written(module, items);
    };
    // In a scroll area: its form would otherwise set the height of every tab and of the docks
    // tabbed with the workbench.
    auto *scroll = new QScrollArea(m_tabs);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_guided = new GuidedPanel(std::move(hooks), scroll);
    scroll->setWidget(m_guided);
    m_tabs->addTab(scroll, QString());
    connect(m_guided, &GuidedPanel::activeChanged, this, &WorkbenchView::updateEnabled);
}

// The reference fingerprint (reference_panel.h) runs its test set on this view's module and set
// value, with its rate and window; its writes go to the journal.
void WorkbenchView::buildReference()
{
    ReferenceHooks hooks;
    hooks.access = [this] { return m_access; };
    hooks.module = [this] { return currentModule(); };
    hooks.moduleAt = [this](int address) -> const model::ModuleInfo * {
        for (const model::ModuleInfo &m : m_modules)
            if (m.address == address)
                return &m;
        return nullptr;
    };
    hooks.setValue = [this] { return currentSetValue(); };
    hooks.rateHz = [this] { return m_rate->value(); };
    hooks.window = [this] {
        return m_useWindow->isChecked() ? std::optional<double>(m_window->value()) : std::nullopt;
    };
    hooks.busy = [this] { return isRunning() || m_guided->isActive(); };
    hooks.written = [this](int module, const std::vector<model::WriteItem> &items) {
        emit written(module, items);
    };
    // In a scroll area, as the guided panel: a low dock keeps the form readable.
    auto *scroll = new QScrollArea(m_tabs);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_reference = new ReferencePanel(std::move(hooks), scroll);
    scroll->setWidget(m_reference);
    m_tabs->addTab(scroll, QString());
    connect(m_reference, &ReferencePanel::activeChanged, this, &WorkbenchView::updateEnabled);
}

bool WorkbenchView::referenceActive() const
{
    return m_reference && m_reference->isActive();
}

} // namespace vt::ui
