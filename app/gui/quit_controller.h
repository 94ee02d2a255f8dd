// QuitController: the one question before the main window closes. It lists what is pending —
// unsaved edits, values the tool changed that drive the actuator (the ActuatorLedger), a running
// workbench test, a monitor step still being written — offers only the choices that apply, and
// carries the answer out in a safe order: save, stop the test (it puts its own set value back),
// let the step's write end, put back, then close the window. Cancel changes nothing.
// Owner: the main window; GUI thread. The views it watches are the window's and outlive it.
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <functional>

class QWidget;

namespace vt::ui {
class StepControl;
class WorkbenchView;
} // namespace vt::ui

namespace vt::app {

class DeviceController;
class FileController;
class Workspace;

// The answers the question can offer.
enum class QuitOption {
    Save,    // save the edits, put back what the tool changed, quit
    PutBack, // put back, quit (unsaved edits are dropped)
    Leave,   // quit without putting back (unsaved edits are dropped)
    Quit,    // quit: nothing to put back was pending (unsaved edits are dropped)
    Cancel,  // stay; nothing changes
};

// What is pending when the person quits.
struct QuitPending
{
    bool unsavedEdits = false;
    QString documentName; // for the sentence about the edits
    bool testRunning = false;
    bool stepBusy = false;
    QStringList putBack; // DeviceController::restoreLines()

    bool any() const { return unsavedEdits || testRunning || stepBusy || !putBack.isEmpty(); }
    // Whether putting back is a choice: something was or is being changed on the device.
    bool putBackChoice() const { return stepBusy || !putBack.isEmpty(); }
};

class QuitController : public QObject
{
    Q_OBJECT
public:
    QuitController(Workspace &workspace, FileController &files, DeviceController &device,
                   ui::WorkbenchView *workbench, ui::StepControl *step, QWidget *window);
    ~QuitController() override;

    // From the window's closeEvent: true when it may close now. Otherwise the question is open
    // (or its answer is being carried out) and the window closes itself when that is done.
    bool mayClose();

    QuitPending pending() const;
    // The choices for `pending`, in the order the buttons show them.
    static QList<QuitOption> options(const QuitPending &pending);
    // A choice's button text.
    static QString optionText(QuitOption option, const QuitPending &pending);
    // The question's text: what is pending and what each choice does with it.
    static QString questionText(const QuitPending &pending);
    // True from the answer until the window closes.
    bool isQuitting() const { return m_state == State::Working; }

    // Tests: answer the question without a dialog (`offered` as the buttons would show them).
    using AnswerHook = std::function<QuitOption(const QuitPending &, const QList<QuitOption> &)>;
    void setAnswerHook(AnswerHook hook) { m_hook = std::move(hook); }

signals:
    void statusMessage(const QString &text);

private:
    enum class State { Idle, Asking, Working, Done };

    void ask(const QuitPending &pending);
    void answer(QuitOption option);
    // Stops the test, waits for it and for the step's write, then puts back (or not) and closes.
    void settle(bool putBack);
    void finish();

    Workspace &m_workspace;
    FileController &m_files;
    DeviceController &m_device;
    QPointer<ui::WorkbenchView> m_workbench;
    QPointer<ui::StepControl> m_step;
    QWidget *m_window;
    AnswerHook m_hook;
    State m_state = State::Idle;
    // The workbench and the step say nothing when a stopped test or a write has ended: the quit
    // looks again on this timer until both are idle or the bound has passed.
    QTimer m_poll;
    int m_polls = 0;
    bool m_putBack = true;
};

} // namespace vt::app
