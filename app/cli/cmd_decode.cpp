// valvetune-cli decode [--protocol P] [--family opat|dma] [--direction request|response]
//                      [--profile KEY] [--dictionary FAMILY] [--cob-id ID] HEX…
// Without --protocol the bytes are auto-detected as the inspector's decode box does, and the
// protocol chosen is named first.
#include "commands.h"
#include "core/hex.h"
#include "dict/dictionary_loader.h"
#include "hcs/profiles.h"
#include "inspect/auto_detect.h"
#include "inspect/describe_any.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

namespace vt::cli {
namespace {

using Json = nlohmann::ordered_json;

const char kUsage[] = "usage: valvetune-cli decode [--protocol "
                      "gateway|modbus-rtu|modbus-tcp|profidrive|pkw|pzd|hart|canopen]\n"
                      "       [--family opat|dma] [--direction request|response] [--profile KEY] "
                      "[--dictionary FAMILY]\n"
                      "       [--cob-id ID] [--lang en|de] HEX...";

std::string fieldText(const dev::FieldSpan &f, dev::Language lang)
{
    return f.text.in(lang);
}

} // namespace

int runDecode(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    if (takeFlag(args, "--help")) {
        ctx.out << kUsage << "\nCMD 15 profiles:";
        for (const auto &p : dev::hcs::allProfiles())
            ctx.out << ' ' << p.key;
        ctx.out << '\n';
        return kExitOk;
    }
    bool missing = false;
    const auto protocolArg = takeOption(args, "--protocol", &missing);
    const auto familyArg = takeOption(args, "--family", &missing);
    const auto directionArg = takeOption(args, "--direction", &missing);
    const auto profileArg = takeOption(args, "--profile", &missing);
    const auto dictionaryArg = takeOption(args, "--dictionary", &missing);
    const auto cobArg = takeOption(args, "--cob-id", &missing);
    const auto langArg = takeOption(args, "--lang", &missing);
    if (missing)
        return ctx.fail(kExitUsage, "an option is missing its value\n" + std::string(kUsage));
    std::optional<dev::FrameFormat> protocol;
    if (protocolArg) {
        protocol = dev::fromKey<dev::FrameFormat>(protocolArg->toStdString());
        if (!protocol)
            return ctx.fail(kExitUsage, "unknown protocol '" + protocolArg->toStdString() + "'");
    }

    dev::AnyOptions options;
    if (familyArg) {
        const auto family = dev::hcs::familyFromName(familyArg->toStdString());
        if (!family)
            return ctx.fail(kExitUsage, "--family takes opat or dma");
        options.family = *family;
    }
    if (directionArg) {
        if (*directionArg == "request")
            options.direction = dev::Direction::Request;
        else if (*directionArg == "response")
            options.direction = dev::Direction::Response;
        else
            return ctx.fail(kExitUsage, "--direction takes request or response");
    }
    if (profileArg)
        options.profile = profileArg->toStdString();
    if (cobArg) {
        const auto cob = parseInteger(*cobArg, 0, 0x7FF);
        if (!cob)
            return ctx.fail(kExitUsage, "--cob-id takes an 11-bit identifier (0..0x7FF)");
        options.cobId = static_cast<std::uint32_t>(*cob);
    }
    dev::Language lang = dev::Language::English;
    if (langArg) {
        if (*langArg != "en" && *langArg != "de")
            return ctx.fail(kExitUsage, "--lang takes en or de");
        lang = *langArg == "de" ? dev::Language::German : dev::Language::English;
    }
    // Parameter names: the dictionary asked for, or the OPAT one (its IDs are unambiguous).
    std::string dictionary = dictionaryArg
                                 ? dictionaryArg->toStdString()
                                 : (options.family == dev::hcs::Family::Opat ? "opat" : "");
    if (!dictionary.empty()) {
        const auto &set = dev::builtinDictionaries();
        options.dictionary = set.ok() ? set->find(dictionary) : nullptr;
        if (!options.dictionary)
            return ctx.fail(kExitUsage, "unknown dictionary '" + dictionary + "'");
    }
    if (args.isEmpty())
        return ctx.fail(kExitUsage, "no frame given\n" + std::string(kUsage));

    const std::string hexText = args.join(' ').toStdString();
    const auto bytes = dev::parseHex(hexText);
    if (!bytes.ok())
        return ctx.fail(kExitUsage, "not hex at character " +
                                        std::to_string(bytes.error().position) + ": " +
                                        bytes.error().reason);

    std::string detected; // "modbus-rtu, request, wrong CRC" when auto-detected
    if (protocol) {
        options.protocol = *protocol;
    } else {
        const auto detection = dev::inspect::detectProtocol(*bytes, options.cobId);
        const dev::inspect::Candidate *c = detection.choice();
        if (!c) {
            std::string names;
            for (const auto &candidate : detection.candidates)
                names += (names.empty() ? "" : ", ") + std::string(dev::key(candidate.protocol));
            return ctx.fail(kExitUsage, names.empty()
                                            ? "the bytes are no frame of any protocol ValveTune "
                                              "knows; give --protocol to see why"
                                            : "cannot tell the protocol (could be " + names +
                                                  "); give --protocol");
        }
        protocol = c->protocol;
        options.protocol = c->protocol;
        // The direction and family asked for when the bytes decode so; else the ones that do.
        if (!c->directions.empty() &&
            (!directionArg || std::find(c->directions.begin(), c->directions.end(),
                                        options.direction) == c->directions.end()))
            options.direction = c->directions.front();
        if (!c->families.empty() && (!familyArg || std::find(c->families.begin(), c->families.end(),
                                                             options.family) == c->families.end()))
            options.family = c->families.front();
        detected = std::string(dev::key(c->protocol)) + ", " +
                   (options.direction == dev::Direction::Request ? "request" : "response") +
                   (c->badCrc ? ", wrong CRC" : "");
    }
    const auto described = dev::describeAny(*bytes, options);
    if (!described.ok())
        return ctx.fail(kExitUsage, described.error());
    const dev::Description &d = *described;

    if (ctx.json) {
        Json fields = Json::array();
        for (const dev::FieldSpan &f : d.fields)
            fields.push_back(Json{{"key", f.key},
                                  {"offset", f.offset},
                                  {"length", f.length},
                                  {"depth", f.depth},
                                  {"value", f.value},
                                  {"text", fieldText(f, lang)}});
        Json error = nullptr;
        if (d.error)
            error = Json{{"offset", d.error->offset},
                         {"reason", dev::describeError(*d.error).in(lang)}};
        ctx.out << Json{{"protocol", dev::key(*protocol)},
                        {"detected", !detected.empty()},
                        {"ok", d.ok()},
                        {"error", error},
                        {"summary", d.summary.in(lang)},
                        {"fields", fields}}
                       .dump(2)
                << '\n';
    } else {
        if (!detected.empty())
            ctx.out << "auto-detected: " << detected << '\n';
        if (!d.summary.in(lang).empty())
            ctx.out << d.summary.in(lang) << '\n';
        for (const dev::FieldSpan &f : d.fields) {
            std::string line(static_cast<std::size_t>(2 * f.depth), ' ');
            line += "[" + std::to_string(f.offset) +
                    (f.length > 1 ? "+" + std::to_string(f.length) : "") + "] ";
            line += f.key;
            if (!f.value.empty())
                line += " = " + f.value;
            if (!fieldText(f, lang).empty())
                line += "  " + fieldText(f, lang);
            ctx.out << line << '\n';
        }
    }
    if (d.error) {
        ctx.err << "valvetune-cli: " << dev::describeError(*d.error).in(lang) << '\n';
        return kExitDeviceError;
    }
    return kExitOk;
}

} // namespace vt::cli
