// FileController: File ▸ New / Open / Save / Save As / Export CSV / Compare with File, recent
// files and the unsaved-changes prompt, for the main window's ParameterDocument. Each action has
// a path-taking form that the menu's file dialog ends in and the tests call directly. GUI thread.
#pragma once

#include "files/param_file.h"

#include <QMessageBox>
#include <QObject>
#include <QStringList>
#include <functional>

class QWidget;

namespace vt::model {
class RecentFiles;
struct NewFileChoice;
} // namespace vt::model

namespace vt::app {

class Workspace;

class FileController : public QObject
{
    Q_OBJECT
public:
    FileController(Workspace &workspace, model::RecentFiles &recent, QWidget *window);

    void newFile(); // asks family, version, mode, modules (NewFileDialog)
    void newFrom(const model::NewFileChoice &choice);
    void open(); // asks for a file
    bool openPath(const QString &path);
    bool save(); // Save As when the document has no file yet
    bool saveAs();
    bool saveTo(const QString &path);
    void exportCsv();
    bool exportCsvTo(const QString &path);
    void compareWithFile();
    // Before the document is replaced or the window closes: Save / Discard / Cancel when there
    // are unsaved edits. False: the user cancelled.
    bool maybeSave();
    // Tests answer the unsaved-changes question without a dialog.
    void setPromptHook(std::function<QMessageBox::StandardButton()> hook)
    {
        m_promptHook = std::move(hook);
    }
    // The last error shown (tests; also in the status bar).
    const QString &lastError() const { return m_lastError; }
    // How the last New or Open paired with the connected node (empty: plainly, or offline).
    const QStringList &lastPairing() const { return m_lastPairing; }

signals:
    void statusMessage(const QString &text);
    // A .vtfold fold plan was opened: the main window shows it in the fold wizard.
    void foldPlanRequested(const QString &path);

private:
    void showPairing(const QStringList &pairing);
    void fail(const QString &message);
    dev::Language language() const;

    Workspace &m_workspace;
    model::RecentFiles &m_recent;
    QWidget *m_window;
    std::function<QMessageBox::StandardButton()> m_promptHook;
    QString m_lastError;
    QStringList m_lastPairing;
};

} // namespace vt::app
