#include "quit_controller.h"

#include "device_controller.h"
#include "file_controller.h"
#include "widgets/monitor/step_control.h"
#include "widgets/tuning/workbench_view.h"
#include "workspace.h"

#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <map>

namespace vt::app {
namespace {

constexpr int kPollMs = 25;
// A stopped test ends within a cycle and its restore (a few paced writes); past this the window
// closes anyway, and the disconnect stops what is left.
constexpr int kMaxPolls = 20'000 / kPollMs;

} // namespace

QuitController::QuitController(Workspace &workspace, FileController &files,
                               DeviceController &device, ui::WorkbenchView *workbench,
                               ui::StepControl *step, QWidget *window)
    : QObject(window), m_workspace(workspace), m_files(files), m_device(device),
      m_workbench(workbench), m_step(step), m_window(window)
{
    m_poll.setSingleShot(true);
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, [this] { settle(m_putBack); });
}

QuitController::~QuitController() = default;

QuitPending QuitController::pending() const
{
    QuitPending p;
    const model::ParameterDocument &doc = m_workspace.document();
    p.unsavedEdits = doc.isModified();
    if (doc.hasFile())
        p.documentName = QFileInfo(doc.filePath()).fileName();
    const bool online = m_workspace.isConnected();
    p.testRunning = online && m_workbench && m_workbench->isRunning();
    p.stepBusy = online && m_step && m_step->isBusy();
    p.putBack = m_device.restoreLines();
    return p;
}

QList<QuitOption> QuitController::options(const QuitPending &pending)
{
    QList<QuitOption> out;
    if (pending.unsavedEdits)
        out << QuitOption::Save;
    if (pending.putBackChoice())
        out << QuitOption::PutBack << QuitOption::Leave;
    else
        out << QuitOption::Quit;
    out << QuitOption::Cancel;
    return out;
}

QString QuitController::optionText(QuitOption option, const QuitPending &p)
{
    switch (option) {
    case QuitOption::Save:
        return p.putBackChoice() ? tr("Save, Put Back and Quit") : tr("Save and Quit");
    case QuitOption::PutBack:
        return p.unsavedEdits ? tr("Put Back, Quit Without Saving") : tr("Put Back and Quit");
    case QuitOption::Leave:
        return p.unsavedEdits ? tr("Quit Without Saving or Putting Back")
                              : tr("Quit Without Putting Back");
    case QuitOption::Quit:
        if (p.unsavedEdits)
            return tr("Quit Without Saving");
        return p.testRunning ? tr("Stop the Test and Quit") : tr("Quit");
    case QuitOption::Cancel: return tr("Cancel");
    }
    return {};
}

QString QuitController::questionText(const QuitPending &p)
{
    QStringList parts;
    if (p.unsavedEdits)
        parts << (p.documentName.isEmpty()
                      ? tr("The parameters have unsaved edits. They are lost unless you save them.")
                      : tr("The parameters in %1 have unsaved edits. They are lost unless you save "
                           "them.")
                            .arg(p.documentName));
    if (p.testRunning)
        parts << tr("A workbench test is running. It is stopped first and puts back the set value "
                    "it drives, whatever you choose.");
    if (p.stepBusy)
        parts << tr("A set value step of the monitor is being written. ValveTune lets the write "
                    "end first.");
    if (!p.putBack.isEmpty())
        parts << tr("ValveTune changed values that drive the actuator:\n%1")
                     .arg(p.putBack.join(QLatin1Char('\n')));
    return tr("Before ValveTune quits:\n\n%1").arg(parts.join(QStringLiteral("\n\n")));
}

bool QuitController::mayClose()
{
    switch (m_state) {
    case State::Done: m_state = State::Idle; return true;
    case State::Asking:
    case State::Working: return false;
    case State::Idle: break;
    }
    const QuitPending p = pending();
    if (!p.any())
        return true;
    ask(p);
    return false;
}

void QuitController::ask(const QuitPending &pending)
{
    m_state = State::Asking;
    const QList<QuitOption> offered = options(pending);
    if (m_hook) {
        answer(m_hook(pending, offered));
        return;
    }
    auto *box = new QMessageBox(QMessageBox::Question, tr("Quit ValveTune"), questionText(pending),
                                QMessageBox::NoButton, m_window);
    box->setObjectName(QStringLiteral("quitQuestion"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    std::map<QAbstractButton *, QuitOption> buttons;
    for (QuitOption option : offered) {
        const QMessageBox::ButtonRole role =
            option == QuitOption::Cancel ? QMessageBox::RejectRole : QMessageBox::AcceptRole;
        QPushButton *button = box->addButton(optionText(option, pending), role);
        buttons[button] = option;
        if (option == offered.front())
            box->setDefaultButton(button);
        if (option == QuitOption::Cancel)
            box->setEscapeButton(button);
    }
    connect(box, &QMessageBox::finished, this, [this, box, buttons](int) {
        const auto it = buttons.find(box->clickedButton());
        answer(it == buttons.end() ? QuitOption::Cancel : it->second);
    });
    box->open();
}

void QuitController::answer(QuitOption option)
{
    switch (option) {
    case QuitOption::Cancel: m_state = State::Idle; return;
    case QuitOption::Save:
        // Before anything on the device changes: a cancelled Save dialog leaves all as it was.
        if (!m_files.save()) {
            m_state = State::Idle;
            emit statusMessage(tr("Not quit: the parameters were not saved."));
            return;
        }
        break;
    case QuitOption::PutBack:
    case QuitOption::Leave:
    case QuitOption::Quit: break;
    }
    m_state = State::Working;
    m_polls = 0;
    // Nothing may start while the answer is carried out.
    m_window->setEnabled(false);
    if (m_workbench && m_workbench->isRunning()) {
        emit statusMessage(tr("Stopping the workbench test before quitting…"));
        m_workbench->stop();
    }
    // Quit was offered when nothing had to be put back; what a stopped test could not restore
    // goes back all the same (the safe side).
    settle(option != QuitOption::Leave);
}

void QuitController::settle(bool putBack)
{
    m_putBack = putBack;
    const bool busy = (m_workbench && m_workbench->isRunning()) || (m_step && m_step->isBusy());
    if (busy && m_workspace.isConnected() && ++m_polls < kMaxPolls) {
        m_poll.start();
        return;
    }
    // Queued: the put-back's report arrives inside the last write's completion, which the
    // disconnect of the closing window must not destroy under it; and without a wait, this runs
    // inside the window's closeEvent, which must end before the window closes again.
    const auto finishLater = [this] {
        QMetaObject::invokeMethod(this, &QuitController::finish, Qt::QueuedConnection);
    };
    if (putBack)
        m_device.putBack(finishLater);
    else
        finishLater();
}

void QuitController::finish()
{
    m_state = State::Done;
    m_window->setEnabled(true);
    m_window->close();
}

} // namespace vt::app
