#include "map_report_dialog.h"

#include "files/param_file_map.h"
#include "model/params/parameter_document.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace vt::ui {

bool MapReportDialog::needed(const model::ParameterDocument &document, const QStringList &pairing)
{
    if (!document.unknownFamilies().empty() || !pairing.isEmpty())
        return true;
    for (const model::ParamModule &m : document.modules()) {
        if (!m.mapReport)
            continue;
        for (const dev::files::RowMapping &r : m.mapReport->rows)
            if (r.status != dev::files::MapStatus::Mapped &&
                r.status != dev::files::MapStatus::Missing)
                return true;
        if (!m.mapReport->notes.empty())
            return true;
    }
    return false;
}

MapReportDialog::MapReportDialog(const model::ParameterDocument &document,
                                 const QStringList &pairing, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("mapReportDialog"));
    setWindowTitle(tr("What Did Not Map"));
    const dev::Language lang = document.language();
    auto q = [lang](const dev::LocalText &t) { return QString::fromStdString(t.in(lang)); };
    if (!pairing.isEmpty()) {
        m_text += tr("With the connected node:") + QLatin1Char('\n');
        for (const QString &line : pairing)
            m_text += QStringLiteral("  ") + line + QLatin1Char('\n');
        m_text += QLatin1Char('\n');
    }
    for (const model::ParamModule &m : document.modules()) {
        if (!m.mapReport)
            continue;
        m_text +=
            tr("Module %1 (%2): %3").arg(m.address).arg(m.identity, q(m.mapReport->summary())) +
            QLatin1Char('\n');
        for (const dev::LocalText &note : m.mapReport->notes)
            m_text += QStringLiteral("  ") + q(note) + QLatin1Char('\n');
        for (const dev::files::RowMapping *r : m.mapReport->problems()) {
            if (r->status == dev::files::MapStatus::Missing)
                continue; // listed in the summary count; the dictionary default or device value
                          // applies
            m_text += QStringLiteral("  %1 — %2: %3\n")
                          .arg(QString::fromStdString(r->name),
                               q(dev::files::statusText(r->status)), q(r->reason));
        }
        m_text += QLatin1Char('\n');
    }
    for (const dev::files::ModuleRecord &r : document.unknownFamilies())
        m_text += tr("Module %1: family \"%2\" is not known to this version; its %n value(s) are "
                     "kept and saved unchanged.",
                     nullptr, static_cast<int>(r.values.size()))
                      .arg(r.address)
                      .arg(QString::fromStdString(r.family)) +
                  QLatin1Char('\n');

    auto *intro = new QLabel(
        tr("Rows that did not map are kept in the file and written back unchanged on save."), this);
    intro->setWordWrap(true);
    auto *view = new QPlainTextEdit(m_text, this);
    view->setReadOnly(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(view, 1);
    layout->addWidget(buttons);
    resize(760, 460);
}

} // namespace vt::ui
