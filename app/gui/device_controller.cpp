#include "device_controller.h"

#include "app_settings.h"
#include "model/params/device_jobs.h"
#include "model/session/actuator_restore.h"
#include "widgets/actuator_confirm.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/editor/compare_dialog.h"
#include "widgets/editor/write_dialog.h"
#include "workspace.h"

#include <QMessageBox>
#include <QProgressDialog>

namespace vt::app {

DeviceController::DeviceController(Workspace &workspace, AppSettings &settings, QWidget *window)
    : QObject(window), m_workspace(workspace), m_settings(settings), m_window(window)
{
    // A failed connect is said in a message, not only in the status bar: started with --connect
    // from a shortcut, the window would otherwise just sit there unconnected.
    connect(&m_workspace, &Workspace::connectFailed, this, &DeviceController::showConnectFailure);
}

DeviceController::~DeviceController() = default;

void DeviceController::connectDialog()
{
    openConnectDialog();
}

void DeviceController::connectDialogOn(model::ConnectionKind kind)
{
    openConnectDialog()->setKind(kind);
}

ui::ConnectDialog *DeviceController::openConnectDialog()
{
    // Remembers every kind's last fields in the settings and opens on the last kind used.
    auto *dialog = new ui::ConnectDialog(m_workspace.dictionaries(), &m_settings.store(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { connectTo(dialog->spec()); });
    dialog->open();
    return dialog;
}

void DeviceController::connectTo(const model::ConnectionSpec &spec)
{
    m_workspace.connectTo(spec);
}

void DeviceController::showConnectFailure(const QString &reason)
{
    if (m_failure)
        m_failure->close();
    m_failure = new QMessageBox(QMessageBox::Warning, tr("Connection Failed"),
                                tr("ValveTune could not connect: %1").arg(reason), QMessageBox::Ok,
                                m_window);
    m_failure->setObjectName(QStringLiteral("connectFailure"));
    m_failure->setAttribute(Qt::WA_DeleteOnClose);
    m_failure->setWindowModality(Qt::WindowModal);
    m_failure->open();
}

void DeviceController::disconnectFromDevice()
{
    offerRestore(tr("Before disconnecting:"), [this] {
        m_workspace.disconnectFromDevice();
        // The report of the put-back stays in view after the disconnect's own status line.
        if (!m_lastRestore.isEmpty())
            emit statusMessage(tr("Disconnected. %1").arg(m_lastRestore));
    });
}

void DeviceController::offerRestore(const QString &when, std::function<void()> then)
{
    m_lastRestore.clear();
    if (m_restore) // a put-back is on its way: this one would ask about the same rows
        return;
    const QStringList lines = restoreLines();
    if (lines.isEmpty()) {
        then();
        return;
    }
    ui::askRestoreActuators(m_window, when, lines, [this, then](bool yes) {
        if (yes)
            putBack(then);
        else
            then();
    });
}

QStringList DeviceController::restoreLines() const
{
    QStringList lines;
    if (!m_workspace.isConnected())
        return lines;
    const dev::Language lang = m_workspace.document().language();
    for (const model::ActuatorChange &c : m_workspace.actuatorLedger().changes())
        lines << (c.original ? ui::actuatorWriteLine(c.module, *c.row, c.now, *c.original, lang)
                             : tr("Module %1: %2 cannot be put back: its value before the change "
                                  "was never read.")
                                   .arg(c.module)
                                   .arg(QString::fromStdString(c.row->name)));
    return lines;
}

void DeviceController::putBack(std::function<void()> then)
{
    if (m_restore) {
        connect(m_restore, &model::ActuatorRestore::finished, this, [then](bool) { then(); });
        return;
    }
    m_lastRestore.clear();
    if (!m_workspace.isConnected() || m_workspace.actuatorLedger().empty()) {
        then();
        return;
    }
    std::map<int, const dev::Dictionary *> dictionaries;
    for (const model::ModuleInfo &info : m_workspace.modules())
        dictionaries[info.address] = info.dictionary;
    m_restore = new model::ActuatorRestore(m_workspace.connection()->access(),
                                           m_workspace.actuatorLedger().restorePlan(),
                                           std::move(dictionaries), this);
    connect(m_restore, &model::ActuatorRestore::finished, this, [this, then](bool) {
        const dev::Language now = m_workspace.document().language();
        QStringList back, notBack;
        std::map<int, std::vector<model::WriteItem>> byModule;
        for (const model::RestoredRow &r : m_restore->results()) {
            byModule[r.module].push_back(r.item);
            const QString name =
                tr("%1 on module %2").arg(QString::fromStdString(r.item.row->name)).arg(r.module);
            if (model::isOnDevice(r.item.status))
                back << name;
            else
                notBack << tr("%1 (%2)").arg(name, model::writeReasonText(r.item, now).isEmpty()
                                                       ? model::writeStatusText(r.item.status)
                                                       : model::writeReasonText(r.item, now));
        }
        for (const model::ActuatorChange &c : m_workspace.actuatorLedger().unrestorable())
            notBack << tr("%1 on module %2 (value before unknown)")
                           .arg(QString::fromStdString(c.row->name))
                           .arg(c.module);
        for (const auto &[module, items] : byModule)
            emit written(module, items);
        m_restore->deleteLater();
        m_restore = nullptr;
        QString text =
            back.isEmpty() ? QString() : tr("Put back: %1.").arg(back.join(QStringLiteral(", ")));
        if (!notBack.isEmpty())
            text += (text.isEmpty() ? QString() : QStringLiteral(" ")) +
                    tr("Not put back: %1.").arg(notBack.join(QStringLiteral(", ")));
        m_lastRestore = text;
        emit statusMessage(text);
        then();
    });
    m_restore->start();
}

void DeviceController::scan()
{
    if (!m_workspace.isConnected())
        return;
    auto *progress = new QProgressDialog(tr("Scanning the node…"), tr("Cancel"), 0, 1, m_window);
    progress->setAttribute(Qt::WA_DeleteOnClose);
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(300);
    connect(&m_workspace, &Workspace::scanProgress, progress, [progress](int done, int total) {
        progress->setMaximum(total);
        progress->setValue(done);
    });
    connect(&m_workspace, &Workspace::scanFinished, progress, [this, progress](int found) {
        progress->close();
        emit statusMessage(tr("Scan found %n module(s).", nullptr, found));
    });
    connect(progress, &QProgressDialog::canceled, this,
            [this] { m_workspace.disconnectFromDevice(); });
    m_workspace.scan();
}

void DeviceController::readAll()
{
    readRows(tr("Reading all parameters…"), {},
             [this](bool complete, const QStringList &problems, const QStringList &warnings) {
                 QString text =
                     complete ? tr("All parameters read.")
                              : tr("Read incomplete: %1")
                                    .arg(problems.isEmpty() ? tr("cancelled")
                                                            : problems.join(QStringLiteral("; ")));
                 // A warning came with a value that was read: said, not a failure.
                 if (!warnings.isEmpty())
                     text += QLatin1Char(' ') +
                             tr("The device warned: %1").arg(warnings.join(QStringLiteral("; ")));
                 emit statusMessage(text);
                 emit readFinished(complete);
             });
}

void DeviceController::readRows(
    const QString &label, std::function<std::vector<const dev::ParamMeta *>(int)> rows,
    std::function<void(bool, const QStringList &, const QStringList &)> then)
{
    if (!m_workspace.isConnected() || m_read)
        return;
    m_read =
        new model::ReadAllJob(m_workspace.connection()->access(), m_workspace.document(), this);
    if (rows)
        m_read->setRows(std::move(rows));
    m_progress = new QProgressDialog(label, tr("Cancel"), 0, 1, m_window);
    m_progress->setObjectName(QStringLiteral("readAllProgress"));
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(300);
    // Queued: once shown, a window-modal QProgressDialog runs the event loop in setValue(), which
    // must not happen inside the session's completion that reports the progress.
    connect(
        m_read, &model::ReadAllJob::progress, m_progress.data(),
        [this](int done, int total) {
            if (!m_progress)
                return;
            m_progress->setMaximum(qMax(total, 1));
            m_progress->setValue(done);
        },
        Qt::QueuedConnection);
    connect(m_progress.data(), &QProgressDialog::canceled, m_read, &model::ReadAllJob::cancel);
    connect(m_read, &model::ReadAllJob::finished, this, [this, then](bool complete) {
        if (m_progress)
            m_progress->close();
        const QStringList problems = m_read->problems();
        const QStringList warnings = m_read->warnings();
        m_read->deleteLater();
        m_read = nullptr;
        then(complete, problems, warnings);
    });
    m_read->start();
}

ui::WriteDialog *DeviceController::writeChanges()
{
    if (!m_workspace.isConnected() || m_read)
        return nullptr;
    const model::ParameterDocument &doc = m_workspace.document();
    bool unknown = false;
    for (int i = 0; i < doc.moduleCount() && !unknown; ++i)
        unknown = !doc.rowsToRead(i).empty();
    if (!unknown)
        return openWriteDialog();
    readRows(
        tr("Reading what the device holds before writing…"),
        [this](int module) { return m_workspace.document().rowsToRead(module); },
        [this](bool complete, const QStringList &problems, const QStringList &) {
            if (!complete) {
                emit statusMessage(
                    tr("Nothing written: the device values could not all be read (%1).")
                        .arg(problems.isEmpty() ? tr("cancelled")
                                                : problems.join(QStringLiteral("; "))));
                return;
            }
            if (auto *dialog = openWriteDialog())
                emit writeDialogOpened(dialog);
        });
    return nullptr;
}

ui::WriteDialog *DeviceController::openWriteDialog()
{
    if (!m_workspace.isConnected())
        return nullptr;
    model::ParameterDocument &doc = m_workspace.document();
    std::vector<model::ModuleWriteResult> plan;
    for (int i = 0; i < doc.moduleCount(); ++i)
        if (doc.module(i).online) {
            auto items = doc.pendingWrites(i);
            if (!items.empty())
                plan.push_back({i, std::move(items)});
        }
    if (plan.empty()) {
        emit statusMessage(tr("Nothing to write: the editor and the device agree."));
        return nullptr;
    }
    auto *dialog =
        new ui::WriteDialog(m_workspace.connection()->access(), doc, std::move(plan), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &ui::WriteDialog::writeFinished, this, [this, dialog](bool complete) {
        for (const model::ModuleWriteResult &r : dialog->job().results())
            emit written(m_workspace.document().module(r.module).address, r.items);
        emit statusMessage(complete
                               ? tr("Every change written and verified.")
                               : tr("Not every change reached the device; see the write results."));
    });
    dialog->open();
    return dialog;
}

void DeviceController::compareWithDevice()
{
    if (!m_workspace.isConnected() || m_read)
        return;
    auto compared = [this](int module) {
        std::vector<const dev::ParamMeta *> rows;
        const model::ParamModule &m = m_workspace.document().module(module);
        for (const dev::ParamMeta *row : model::readableRows(*m.dictionary, m.version, m.mode))
            if (row->writable() && dev::files::isFileRow(*row))
                rows.push_back(row);
        return rows;
    };
    readRows(tr("Reading the device to compare…"), compared,
             [this](bool complete, const QStringList &problems, const QStringList &) {
                 if (!complete) {
                     emit statusMessage(tr("Not compared: the device could not be read (%1).")
                                            .arg(problems.isEmpty()
                                                     ? tr("cancelled")
                                                     : problems.join(QStringLiteral("; "))));
                     return;
                 }
                 auto *dialog = new ui::CompareDialog(m_workspace.document(), m_window);
                 dialog->setAttribute(Qt::WA_DeleteOnClose);
                 dialog->compareWithDevice();
                 dialog->open();
                 emit compareDialogOpened(dialog);
             });
}

} // namespace vt::app
