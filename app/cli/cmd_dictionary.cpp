// valvetune-cli dictionary list | show FAMILY [--lang en|de] [--json]
#include "commands.h"
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"

#include <cstdio>
#include <iomanip>
#include <nlohmann/json.hpp>

namespace vt::cli {
namespace {

using Json = nlohmann::ordered_json;

const char kUsage[] = "usage: valvetune-cli dictionary list | show FAMILY [--lang en|de] [--json]";

Json number(double v)
{
    if (v == static_cast<double>(static_cast<long long>(v)))
        return static_cast<long long>(v);
    return v;
}

Json rowJson(const dev::ParamMeta &p)
{
    Json j;
    j["name"] = p.name;
    if (p.id)
        j["id"] = *p.id;
    if (p.ind)
        j["ind"] = *p.ind;
    if (p.pnu)
        j["pnu"] = *p.pnu;
    if (p.ind)
        j["instance"] = p.instance;
    if (p.pzd)
        j["pzd"] = *p.pzd;
    j["block"] = p.block;
    if (p.branch)
        j["branch"] = p.branch;
    j["access"] = dev::accessKey(p.access);
    j["type"] = dev::rawTypeKey(p.type);
    if (p.isString()) {
        j["length"] = p.length;
        j["min"] = nullptr;
        j["max"] = nullptr;
    } else {
        j["min"] = number(p.min);
        j["max"] = number(p.max);
        j["step"] = number(p.step);
    }
    j["default"] = p.defaultValue ? number(*p.defaultValue) : Json(nullptr);
    j["default_assumed"] = p.defaultAssumed;
    j["unit"] = p.unit;
    if (p.scale.name.empty())
        j["scale"] = nullptr;
    else
        j["scale"] =
            Json{{"name", p.scale.name},
                 {"factor", p.scale.factor},
                 {"decimals", p.scale.decimals},
                 {"rounding", p.scale.rounding == dev::Rounding::Truncate ? "truncate" : "nearest"},
                 {"assumed", p.scale.assumed}};
    Json enums = Json::array();
    for (const auto &e : p.enums)
        enums.push_back(Json{{"value", e.value}, {"en", e.text.en}, {"de", e.text.de}});
    j["enum"] = enums;
    Json bits = Json::array();
    for (const auto &b : p.bits)
        bits.push_back(Json{{"bit", b.bit}, {"en", b.text.en}, {"de", b.text.de}});
    j["bits"] = bits;
    j["modes"] = p.modes;
    j["versions"] = p.versions;
    j["persistence"] = p.persistence == dev::Persistence::Eeprom     ? "eeprom"
                       : p.persistence == dev::Persistence::Volatile ? "volatile"
                                                                     : "";
    if (p.canopen)
        j["canopen"] = Json{{"index", p.canopen->index}, {"sub", p.canopen->sub}};
    j["label_en"] = p.label.en;
    j["label_de"] = p.label.de;
    j["description_en"] = p.description.en;
    j["description_de"] = p.description.de;
    return j;
}

std::string rangeText(const dev::ParamMeta &p, dev::Language lang)
{
    if (p.isString())
        return std::to_string(p.length) + " bytes";
    if (!p.enums.empty() && p.enums.size() <= 3) {
        std::string s;
        for (const auto &e : p.enums)
            s += (s.empty() ? "" : " | ") + std::to_string(e.value) + "=" + e.text.in(lang);
        return s;
    }
    return dev::formatValue(p, p.min, lang) + " … " + dev::formatValue(p, p.max, lang);
}

} // namespace

int runDictionary(const QStringList &argsIn, Context &ctx)
{
    QStringList args = argsIn;
    dev::Language lang = dev::Language::English;
    if (const qsizetype i = args.indexOf(QStringLiteral("--lang")); i >= 0) {
        if (i + 1 >= args.size() || (args[i + 1] != "en" && args[i + 1] != "de"))
            return ctx.fail(kExitUsage, "--lang takes en or de");
        lang = args[i + 1] == "de" ? dev::Language::German : dev::Language::English;
        args.remove(i, 2);
    }
    if (args.contains(QStringLiteral("--help"))) {
        ctx.out << kUsage << '\n';
        return kExitOk;
    }
    if (args.isEmpty())
        return ctx.fail(kExitUsage, kUsage);

    const auto &loaded = dev::builtinDictionaries();
    if (!loaded.ok())
        return ctx.fail(kExitDeviceError, "broken dictionary: " + loaded.error().front().text());
    const dev::DictionarySet &set = *loaded;

    const QString verb = args.takeFirst();
    if (verb == "list" && args.isEmpty()) {
        if (ctx.json) {
            Json list = Json::array();
            for (const auto &f : set.families()) {
                const dev::Dictionary *d = set.find(f);
                list.push_back(Json{{"family", f},
                                    {"title_en", d->title.en},
                                    {"title_de", d->title.de},
                                    {"vendor", d->vendor},
                                    {"protocol", dev::key(d->protocol)},
                                    {"versions", d->versions},
                                    {"modes", d->modes},
                                    {"rows", d->params.size()}});
            }
            ctx.out << Json{{"families", list}}.dump(2) << '\n';
        } else {
            for (const auto &f : set.families()) {
                const dev::Dictionary *d = set.find(f);
                ctx.out << std::left << std::setw(14) << f << std::setw(5) << d->params.size()
                        << d->title.in(lang) << '\n';
            }
        }
        return kExitOk;
    }
    if (verb == "show" && args.size() == 1) {
        const std::string family = args.first().toStdString();
        const dev::Dictionary *d = set.find(family);
        if (!d || d->abstract)
            return ctx.fail(kExitUsage,
                            "unknown family '" + family + "' (see: valvetune-cli dictionary list)");
        if (ctx.json) {
            Json rows = Json::array();
            for (const auto &p : d->params)
                rows.push_back(rowJson(p));
            ctx.out << Json{{"family", d->family},
                            {"title_en", d->title.en},
                            {"title_de", d->title.de},
                            {"vendor", d->vendor},
                            {"protocol", dev::key(d->protocol)},
                            {"source", d->source},
                            {"versions", d->versions},
                            {"modes", d->modes},
                            {"parameters", rows}}
                           .dump(2)
                    << '\n';
        } else {
            ctx.out << d->title.in(lang) << " — " << d->source << '\n';
            for (const auto &p : d->params)
                ctx.out << std::left << std::setw(28) << p.name << std::setw(18) << p.addressText()
                        << std::setw(4) << dev::accessKey(p.access) << std::setw(8)
                        << dev::rawTypeKey(p.type) << p.label.in(lang) << "  ["
                        << rangeText(p, lang) << "]\n";
        }
        return kExitOk;
    }
    return ctx.fail(kExitUsage, kUsage);
}

} // namespace vt::cli
