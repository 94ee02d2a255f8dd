#include "connection_args.h"

#include "app/cmdline/arg_parse.h"
#include "app/cmdline/connection_options.h"

namespace vt::cli {

std::string deviceSynopsis()
{
    return std::string(cmdline::kConnectionSynopsis) +
           "\n     [--module ADDRESS] [--lang en|de] [--json]";
}

std::optional<QString> leftoverOption(const QStringList &args)
{
    for (const QString &a : args) {
        if (a.startsWith(QLatin1String("--")))
            return a;
    }
    return std::nullopt;
}

dev::Result<DeviceOptions, std::string> takeDeviceOptions(QStringList &args)
{
    bool missing = false;
    const auto module = cmdline::takeOption(args, "--module", &missing);
    const auto lang = cmdline::takeOption(args, "--lang", &missing);
    if (missing)
        return std::string("an option is missing its value");
    auto spec = cmdline::takeConnectionOptions(args);
    if (!spec.ok())
        return spec.error();

    DeviceOptions o;
    o.spec = *spec;
    if (module) {
        const auto m = cmdline::parseInteger(*module, 0, 255);
        if (!m)
            return std::string("--module takes a module address 0..255");
        o.module = static_cast<int>(*m);
    }
    if (lang) {
        if (*lang != "en" && *lang != "de")
            return std::string("--lang takes en or de");
        o.lang = *lang == "de" ? dev::Language::German : dev::Language::English;
    }
    return o;
}

} // namespace vt::cli
