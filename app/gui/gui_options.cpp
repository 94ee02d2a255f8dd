#include "gui_options.h"

#include "app/cmdline/connection_options.h"
#include "dict/dictionary_loader.h"
#include "language.h"
#include "model/session/sim_endpoint.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace vt::app {
namespace {

GuiOptions usageError(const QString &error)
{
    GuiOptions out;
    out.error = error;
    out.exitNow = true;
    out.exitCode = 2;
    return out;
}

} // namespace

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
    const QCommandLineOption connectOption(
        QStringList{QStringLiteral("connect")},
        QStringLiteral("Connect at start-up, with valvetune-cli's connection options (below)."));
    const QCommandLineOption factory(
        QStringList{QStringLiteral("factory")},
        QStringLiteral("With --simulate: start the simulator from the bare dictionary defaults "
                       "instead of a commissioned machine."));
    const QCommandLineOption auditDir(
        QStringList{QStringLiteral("audit-dir")},
        QStringLiteral("Keep the session log (every write, one JSON line each) in DIR instead of "
                       "the default (~/.local/share/ValveTune/sessions, or "
                       "$VT_AUDIT_DIR)."),
        QStringLiteral("DIR"));
    parser.addOptions({lang, simulate, factory, open, connectOption, auditDir});
    // A file manager and the desktop entry (Exec=valvetune %f) pass the file as the argument.
    parser.addPositionalArgument(
        QStringLiteral("FILE"),
        QStringLiteral("A parameter file (.vtpar) or fold plan (.vtfold) to open, as --open does."),
        QStringLiteral("[FILE]"));

    if (helpText)
        *helpText = parser.helpText() + QLatin1Char('\n') +
                    QString::fromLatin1(cmdline::kConnectionSynopsis) + QLatin1Char('\n');
    // The connection options go to the parser valvetune-cli uses; QCommandLineParser sees the rest.
    QStringList rest = arguments;
    if (rest.contains(QStringLiteral("--connect"))) {
        auto spec = cmdline::takeConnectionOptions(rest);
        if (!spec.ok())
            return usageError(
                QStringLiteral("--connect: %1").arg(QString::fromStdString(spec.error())));
        out.connection = *spec;
    } else if (cmdline::hasConnectionOption(rest)) {
        return usageError(QStringLiteral(
            "--sim, --port, --tcp, --can, --hart and their settings go with --connect"));
    }
    if (!parser.parse(rest)) {
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
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return usageError(QStringLiteral("unexpected argument '%1': give one file").arg(files[1]));
    if (!files.isEmpty() && parser.isSet(open))
        return usageError(QStringLiteral("give one file: '%1' or --open").arg(files.first()));
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
    out.factory = parser.isSet(factory);
    out.auditDir = parser.value(auditDir);
    if (out.factory && out.simulate.isEmpty())
        return usageError(QStringLiteral("--factory goes with --simulate (or --connect --sim)"));
    if (parser.isSet(open))
        out.openFile = parser.value(open);
    else if (!files.isEmpty())
        out.openFile = files.first();
    if (out.connection && !out.simulate.isEmpty())
        return usageError(QStringLiteral("give one connection: --simulate or --connect"));
    return out;
}

} // namespace vt::app
