// File ▸ Commissioning Report…: the header (customer, machine, axis, operator, comment; remembered
// in QSettings), the workbench runs to include, a reference parameter file, the report's language
// and format, a print preview and Save. The report itself is made by whoever opens the dialog
// (ReportMaker): it knows the node, the session's writes and the words of the chosen language.
// Owner: the main window (a child dialog); GUI thread.
#pragma once

#include "core/local_text.h"
#include "model/report/report.h"

#include <QDialog>
#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPrinter;

namespace vt::ui {

struct ReportChoice
{
    model::ReportHeader header;
    std::vector<int> runs; // indices into the titles the dialog was given
    QString referenceFile;
    bool drift = false; // the Workbench's last comparison with a reference fingerprint
    dev::Language lang = dev::Language::English;
};

// Makes the report for `choice` and hands it to `use` while the words of choice.lang are in force;
// returns an empty string, or why no report could be made (for people).
using ReportMaker = std::function<QString(const ReportChoice &choice,
                                          const std::function<void(const model::Report &)> &use)>;

class ReportDialog : public QDialog
{
    Q_OBJECT
public:
    ReportDialog(const QStringList &runTitles, dev::Language lang, ReportMaker maker,
                 QWidget *parent = nullptr);
    ~ReportDialog() override;

    // The Workbench compared the module with a reference fingerprint (`what` names it): offer
    // its drift for the report, ticked.
    void offerDrift(const QString &what);
    ReportChoice choice() const;
    // Remembers the header, then writes the report to `path` in the format its suffix names;
    // empty, or why not.
    QString saveTo(const QString &path);

private:
    void preview();
    void save();
    void paint(QPrinter *printer);
    void remember() const;

    ReportMaker m_maker;
    QLineEdit *m_customer = nullptr;
    QLineEdit *m_machine = nullptr;
    QLineEdit *m_axis = nullptr;
    QLineEdit *m_operator = nullptr;
    QPlainTextEdit *m_comment = nullptr;
    QListWidget *m_runs = nullptr;
    QLineEdit *m_reference = nullptr;
    QCheckBox *m_drift = nullptr;
    QComboBox *m_lang = nullptr;
    QComboBox *m_format = nullptr;
};

} // namespace vt::ui
