#include "file_controller.h"

#include "model/params/param_file_io.h"
#include "model/recent_files.h"
#include "widgets/editor/compare_dialog.h"
#include "widgets/editor/map_report_dialog.h"
#include "widgets/files/new_file_dialog.h"
#include "workspace.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QStandardPaths>

namespace vt::app {
namespace {

QString fileFilter()
{
    return FileController::tr(
        "ValveTune parameter files (*.vtpar);;Fold plans (*.vtfold);;All files (*)");
}

} // namespace

FileController::FileController(Workspace &workspace, model::RecentFiles &recent, QWidget *window)
    : QObject(window), m_workspace(workspace), m_recent(recent), m_window(window)
{
}

dev::Language FileController::language() const
{
    return m_workspace.document().language();
}

void FileController::fail(const QString &message)
{
    m_lastError = message;
    emit statusMessage(message);
    if (!m_promptHook) // interactive: tell the user; tests read lastError()
        QMessageBox::warning(m_window, tr("ValveTune"), message);
}

bool FileController::maybeSave()
{
    if (!m_workspace.document().isModified())
        return true;
    const QMessageBox::StandardButton answer =
        m_promptHook
            ? m_promptHook()
            : QMessageBox::question(m_window, tr("Unsaved Changes"),
                                    tr("The parameters have unsaved changes. Save them first?"),
                                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                    QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void FileController::newFile()
{
    if (!maybeSave())
        return;
    auto *dialog = new ui::NewFileDialog(m_workspace.dictionaries(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // Offer the connected device's family first.
    if (!m_workspace.modules().empty() && m_workspace.modules().front().dictionary)
        dialog->setFamily(m_workspace.modules().front().dictionary->family);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { newFrom(dialog->choice()); });
    dialog->open();
}

void FileController::newFrom(const model::NewFileChoice &choice)
{
    if (!choice.valid())
        return;
    model::ParameterDocument &doc = m_workspace.document();
    doc.createNew(choice, m_workspace.dictionaries());
    // Still connected: the new modules pair with the node's; the node's others stay out.
    if (m_workspace.isConnected())
        showPairing(doc.attachDevice(m_workspace.modules(), false));
    emit statusMessage(tr("New parameter set for %1 with the dictionary's defaults.")
                           .arg(QString::fromStdString(choice.dictionary->family)));
}

void FileController::showPairing(const QStringList &pairing)
{
    m_lastPairing = pairing;
    if (pairing.isEmpty() || m_promptHook)
        return;
    auto *report = new ui::MapReportDialog(m_workspace.document(), pairing, m_window);
    report->setAttribute(Qt::WA_DeleteOnClose);
    report->open();
}

void FileController::open()
{
    if (!maybeSave())
        return;
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open Parameter File"), QString(), fileFilter());
    if (!path.isEmpty())
        openPath(path);
}

bool FileController::openPath(const QString &path)
{
    // A fold plan (the fold wizard's file) opens in the wizard, not in the parameter editor.
    if (QFileInfo(path).suffix().compare(QLatin1String("vtfold"), Qt::CaseInsensitive) == 0) {
        m_recent.add(QFileInfo(path).absoluteFilePath());
        emit foldPlanRequested(QFileInfo(path).absoluteFilePath());
        return true;
    }
    auto file = model::readParamFile(path, language());
    if (!file.ok()) {
        m_recent.remove(path);
        fail(file.error());
        return false;
    }
    model::ParameterDocument &doc = m_workspace.document();
    doc.loadFile(*file, m_workspace.dictionaries(), QFileInfo(path).absoluteFilePath());
    // Still connected: the file's modules pair with the node's; the Device column stays.
    QStringList pairing;
    if (m_workspace.isConnected())
        pairing = doc.attachDevice(m_workspace.modules(), false);
    m_lastPairing = pairing;
    m_recent.add(QFileInfo(path).absoluteFilePath());
    emit statusMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)));
    if (ui::MapReportDialog::needed(doc, pairing) && !m_promptHook) {
        auto *report = new ui::MapReportDialog(doc, pairing, m_window);
        report->setAttribute(Qt::WA_DeleteOnClose);
        report->open();
    }
    return true;
}

bool FileController::save()
{
    const model::ParameterDocument &doc = m_workspace.document();
    return doc.hasFile() ? saveTo(doc.filePath()) : saveAs();
}

bool FileController::saveAs()
{
    const model::ParameterDocument &doc = m_workspace.document();
    QString suggestion = doc.filePath();
    if (suggestion.isEmpty())
        suggestion = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) +
                     QStringLiteral("/parameters.vtpar");
    QString path =
        QFileDialog::getSaveFileName(m_window, tr("Save Parameter File"), suggestion, fileFilter());
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".vtpar");
    return saveTo(path);
}

bool FileController::saveTo(const QString &path)
{
    model::ParameterDocument &doc = m_workspace.document();
    if (doc.moduleCount() == 0 && doc.unknownFamilies().empty()) {
        fail(tr("There are no parameters to save."));
        return false;
    }
    const std::string tool = "ValveTune " + QCoreApplication::applicationVersion().toStdString();
    if (auto error = model::saveParamFile(path, doc.toParamFile(tool), m_workspace.dictionaries(),
                                          language())) {
        fail(*error);
        return false;
    }
    doc.markSaved(QFileInfo(path).absoluteFilePath());
    m_recent.add(QFileInfo(path).absoluteFilePath());
    emit statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void FileController::exportCsv()
{
    QString path = QFileDialog::getSaveFileName(m_window, tr("Export CSV"), QString(),
                                                tr("CSV files (*.csv);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".csv");
    exportCsvTo(path);
}

bool FileController::exportCsvTo(const QString &path)
{
    const model::ParameterDocument &doc = m_workspace.document();
    if (auto error = model::exportParamCsv(path, doc.toParamFile({}), m_workspace.dictionaries(),
                                           language())) {
        fail(*error);
        return false;
    }
    emit statusMessage(
        language() == dev::Language::German
            ? tr("Exported %1 (separator ';', decimal comma)").arg(QDir::toNativeSeparators(path))
            : tr("Exported %1 (separator ',', decimal point)").arg(QDir::toNativeSeparators(path)));
    return true;
}

void FileController::compareWithFile()
{
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Compare with File"), QString(), fileFilter());
    if (path.isEmpty())
        return;
    auto file = model::readParamFile(path, language());
    if (!file.ok()) {
        fail(file.error());
        return;
    }
    auto *dialog = new ui::CompareDialog(m_workspace.document(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->compareWithFile(*file, QFileInfo(path).fileName());
    dialog->open();
}

} // namespace vt::app
