#include "report_controller.h"

#include "app/i18n/translation.h"
#include "files/file_rows.h"
#include "language.h"
#include "model/audit/audit_log.h"
#include "model/params/param_file_io.h"
#include "model/params/parameter_tree_model.h"
#include "model/report/report_drift.h"
#include "model/report/report_render.h"
#include "model/report/report_writes.h"
#include "widgets/report/report_dialog.h"
#include "widgets/tuning/reference_panel.h"
#include "widgets/tuning/workbench_view.h"
#include "workspace.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QTranslator>
#include <memory>

namespace vt::app {

namespace {

// English words whatever catalogue is in force: every text comes back as its source (the
// catalogue for "en" holds plural forms only, so it cannot override a German one).
class SourceWords : public QTranslator
{
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *, const char *source, const char *, int) const override
    {
        return QString::fromUtf8(source);
    }
};

// The words and the number format of `lang` while the report is made, when they are not the
// UI's; the UI's again afterwards.
class ReportWords
{
public:
    ReportWords(dev::Language lang, const QString &uiCode)
    {
        const QString code =
            lang == dev::Language::German ? QStringLiteral("de") : QStringLiteral("en");
        if (code == uiCode)
            return;
        m_locale = QLocale();
        QLocale::setDefault(
            QLocale(lang == dev::Language::German ? QLocale::German : QLocale::English));
        if (lang == dev::Language::German) {
            m_german = i18n::Translation::load(code);
            if (m_german)
                m_german->install();
        } else {
            m_source = std::make_unique<SourceWords>();
            QCoreApplication::installTranslator(m_source.get());
        }
    }
    ~ReportWords()
    {
        if (m_source)
            QCoreApplication::removeTranslator(m_source.get());
        if (m_locale)
            QLocale::setDefault(*m_locale);
    }
    ReportWords(const ReportWords &) = delete;
    ReportWords &operator=(const ReportWords &) = delete;

private:
    std::optional<QLocale> m_locale;
    std::unique_ptr<i18n::Translation> m_german;
    std::unique_ptr<SourceWords> m_source;
};

} // namespace

ReportController::ReportController(Workspace &workspace, Language &language,
                                   ui::WorkbenchView &workbench, QObject *parent)
    : QObject(parent), m_workspace(workspace), m_language(language), m_workbench(workbench)
{
}

ReportController::~ReportController() = default;

void ReportController::openDialog(QWidget *parent)
{
    QStringList titles;
    for (const auto &run : m_workbench.runs())
        titles << model::runTitle(*run);
    const dev::Language uiLang = m_language.current() == QLatin1String("de")
                                     ? dev::Language::German
                                     : dev::Language::English;
    const auto maker = [this](const ui::ReportChoice &choice,
                              const std::function<void(const model::Report &)> &use) -> QString {
        ReportWords words(choice.lang, m_language.current());
        model::ParameterDocument &doc = m_workspace.document();
        if (doc.moduleCount() == 0)
            return ReportController::tr(
                "There is nothing to report: connect to a node or open a parameter file first.");
        model::ReportInput input;
        input.header = choice.header;
        input.settings = doc.toParamFile(std::string("ValveTune ") + VT_VERSION);
        const bool online = m_workspace.isConnected();
        for (dev::files::ModuleRecord &record : input.settings.modules) {
            const int index = doc.findModule(record.address);
            if (!online || index < 0 || !doc.module(index).paired || !doc.module(index).dictionary)
                continue;
            record.values.clear();
            for (const dev::ParamMeta &row : doc.module(index).dictionary->params)
                if (dev::files::isFileRow(row))
                    if (const auto value = doc.value(index, &row, model::Layer::Device))
                        record.values.push_back(dev::files::makeValueRow(row, *value));
        }
        if (online && m_workspace.connection())
            input.connection = m_workspace.connection()->describe();
        else
            input.sourceFile = doc.filePath();
        for (const model::ModuleInfo &m : m_workspace.modules())
            if (!m.identityText.en.empty())
                input.identities[m.address] = m.identityText;
        if (!choice.referenceFile.isEmpty()) {
            auto reference = model::readParamFile(choice.referenceFile, choice.lang);
            if (!reference.ok())
                return reference.error();
            input.reference = std::move(*reference);
            input.referenceFile = choice.referenceFile;
        }
        const auto &runs = m_workbench.runs();
        for (int index : choice.runs)
            if (index >= 0 && static_cast<std::size_t>(index) < runs.size())
                input.runs.push_back(*runs[static_cast<std::size_t>(index)]);
        // Every write of this session from any window, as the session log on disk holds it.
        if (const model::AuditLog *log = model::AuditLog::current(); log && !log->path().isEmpty())
            input.writes = model::reportWrites(model::readAuditLog(log->path()), input.settings,
                                               m_workspace.dictionaries(), choice.lang);
        const ui::ReferencePanel *panel = m_workbench.referencePanel();
        if (choice.drift && panel && panel->comparison() && panel->reference()) {
            const model::Reference &reference = *panel->reference();
            input.drift = model::reportDrift(
                reference, *panel->comparison(), panel->referencePath(),
                m_workspace.dictionaries().find(reference.file.family), choice.lang);
        }
        use(model::assembleReport(std::move(input), m_workspace.dictionaries(), choice.lang));
        return {};
    };
    auto *dialog = new ui::ReportDialog(titles, uiLang, maker, parent);
    if (const ui::ReferencePanel *panel = m_workbench.referencePanel();
        panel && panel->comparison() && panel->reference())
        dialog->offerDrift(QFileInfo(panel->referencePath()).fileName());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

} // namespace vt::app
