#include "gui_options.h"

#include "dict/dictionary_loader.h"
#include "language.h"
#include "model/session/sim_endpoint.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace vt::app {

GuiOptions parseGuiOptions(const QStringList &arguments, QString *helpText)
{
    GuiOptions out;
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("ValveTune: parameterisation and tuning of hydraulic valve electronics."));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QCommandLineOption lang(QStringList{QStringLiteral("lang")},
                                  QStringLiteral("User interface language: en or de."),
                                  QStringLiteral("en|de"));
    const QCommandLineOption simulate(
        QStringList{QStringLiteral("simulate")},
        QStringLiteral("Connect to the built-in simulator of FAMILY at start-up."),
        QStringLiteral("FAMILY[:MODULES]"));
    const QCommandLineOption open(QStringList{QStringLiteral("open")},
                                  QStringLiteral("Open a parameter file at start-up."),
                                  QStringLiteral("FILE"));
    parser.addOptions({lang, simulate, open});

    if (helpText)
        *helpText = parser.helpText();
    if (!parser.parse(arguments)) {
        out.error = parser.errorText();
        out.exitNow = true;
        out.exitCode = 2;
        return out;
    }
    if (parser.isSet(help) || parser.isSet(version)) {
        out.exitNow = true;
        out.exitCode = parser.isSet(help) ? -1 : -2; // main() prints help / version
        return out;
    }
    if (!parser.positionalArguments().isEmpty()) {
        out.error =
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().first());
        out.exitNow = true;
        out.exitCode = 2;
        return out;
    }
    if (parser.isSet(lang)) {
        out.language = parser.value(lang);
        if (!Language::isKnown(out.language)) {
            out.error = QStringLiteral("--lang takes en or de, not '%1'").arg(out.language);
            out.exitNow = true;
            out.exitCode = 2;
            return out;
        }
    }
    if (parser.isSet(simulate)) {
        out.simulate = parser.value(simulate);
        const auto spec = model::parseSimSpec(out.simulate);
        QString problem = spec.ok() ? QString() : spec.error();
        if (spec.ok() && !dev::builtinDictionaries()->find(spec->family))
            problem = QStringLiteral("unknown family '%1' (valvetune-cli dictionary lists them)")
                          .arg(QString::fromStdString(spec->family));
        if (!problem.isEmpty()) {
            out.error = QStringLiteral("--simulate: %1").arg(problem);
            out.exitNow = true;
            out.exitCode = 2;
            return out;
        }
    }
    if (parser.isSet(open))
        out.openFile = parser.value(open);
    return out;
}

} // namespace vt::app
