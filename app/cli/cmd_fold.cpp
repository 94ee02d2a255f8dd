// valvetune-cli fold: the module-fold PLC plan without the GUI.
//   fold plan --node opat|dma-pb|dma-pn --modules N [--product NUMBER] [--lang en|de]
// prints what the PLC programmer configures for a node with N modules in all (OPAT: the master
// plus N-1 CAN slaves): GSD file and module, output/input lengths and the byte map per module.
#include "commands.h"
#include "core/hex.h"
#include "model/fold/fold_export.h"
#include "model/fold/plc_config.h"

#include <nlohmann/json.hpp>

namespace vt::cli {
namespace {

using Json = nlohmann::ordered_json;

const char kUsage[] = "usage: valvetune-cli fold plan --node opat|dma-pb|dma-pn --modules N "
                      "[--product NUMBER] [--lang en|de]\n"
                      "N counts every module: OPAT 1..8 (the master plus N-1 CAN slaves), DMA 1..5 "
                      "(CMD 15 reaches E22 = 1..5).\n"
                      "--product: DMA PROFIBUS node product number, which decides the GSD file "
                      "(\"5 005 xxx x5\": hcs0ea7.gsd).";

Json byteJson(const model::PlcImageByte &b, dev::Language lang)
{
    return Json{{"byte", b.offset},
                {"field", b.field},
                {"meaning", model::plcText(b.text, lang).toStdString()}};
}

Json bitsJson(const std::array<dev::hcs::BitMeaning, 8> &bits, dev::Language lang)
{
    Json list = Json::array();
    for (const auto &bit : bits)
        if (bit.used)
            list.push_back(Json{{"mask", bit.mask},
                                {"name", std::string(bit.name)},
                                {"meaning", bit.text.in(lang)}});
    return list;
}

Json planJson(const model::PlcConfig &c, const model::FoldPlan &plan, dev::Language lang)
{
    Json map = Json::array();
    for (const model::PlcModuleSection &s : c.sections) {
        const auto &info = dev::hcs::profileInfo(s.profile);
        Json bytes = Json::array();
        for (const auto &b : c.output)
            if (b.module == s.module)
                bytes.push_back(byteJson(b, lang));
        const auto &m = plan.modules[static_cast<std::size_t>(s.module)];
        map.push_back(Json{
            {"module", s.module + 1},
            {"address", m.address},
            {"sadr", s.sadr},
            {"layout", std::string(info.key)},
            {"output_first", s.outputFirst},
            {"output_last", s.outputFirst + s.outputLength - 1},
            {"output", bytes},
            {"answer", Json{{"value1", std::string(info.response1.parameter) + " " +
                                           info.response1.text.in(lang)},
                            {"value2", std::string(info.response2.parameter) + " " +
                                           info.response2.text.in(lang)}}},
            {"control_bits", bitsJson(s.controlBits, lang)},
            {"status_high_bits", bitsJson(s.statusHighBits, lang)},
            {"status_low_bits", bitsJson(s.statusLowBits, lang)},
        });
    }
    Json header = Json::array();
    for (const auto &b : c.output)
        if (b.module < 0)
            header.push_back(byteJson(b, lang));
    Json input = Json::array();
    for (const auto &b : c.input)
        input.push_back(byteJson(b, lang));
    return Json{
        {"node", std::string(model::foldNodeKey(c.node))},
        {"modules", c.modules},
        {"gsd_file", c.gsdFile},
        {"gsd_device", c.gsdDevice},
        {"gsd_module", c.gsdModule},
        {"output_bytes", c.outputBytes},
        {"input_bytes", c.inputBytes},
        {"reserved_output_bytes", c.moduleOutputBytes},
        {"reserved_input_bytes", c.moduleInputBytes},
        {"snum", c.snum},
        {"output_header", header},
        {"map", map},
        {"input", input},
        {"example_request", dev::toHex(c.exampleRequestBytes)},
        {"source", model::plcText(c.gsdNote, lang).toStdString()},
    };
}

int runPlan(QStringList rest, Context &ctx)
{
    bool missing = false;
    const auto nodeText = takeOption(rest, "--node", &missing);
    if (!nodeText)
        return ctx.fail(kExitUsage, "fold plan: --node opat|dma-pb|dma-pn is required");
    const auto node = model::foldNodeFromKey(nodeText->toStdString());
    if (!node)
        return ctx.fail(kExitUsage, "fold plan: --node takes opat, dma-pb or dma-pn, not '" +
                                        nodeText->toStdString() + "'");
    const auto countText = takeOption(rest, "--modules", &missing);
    if (!countText)
        return ctx.fail(kExitUsage, "fold plan: --modules N is required");
    const auto count = parseInteger(*countText, 1, 1000);
    if (!count)
        return ctx.fail(kExitUsage,
                        "fold plan: --modules takes a module count of at least 1, not '" +
                            countText->toStdString() + "'");
    const auto product = takeOption(rest, "--product", &missing);
    dev::Language lang = dev::Language::English;
    if (const auto langText = takeOption(rest, "--lang", &missing)) {
        if (*langText != "en" && *langText != "de")
            return ctx.fail(kExitUsage, "fold plan: --lang takes en or de");
        lang = *langText == "de" ? dev::Language::German : dev::Language::English;
    }
    if (missing)
        return ctx.fail(kExitUsage, "fold plan: an option is missing its value (see fold --help)");
    ctx.useLanguage(lang);
    if (!rest.isEmpty())
        return ctx.fail(kExitUsage,
                        "fold plan: unexpected argument '" + rest.first().toStdString() + "'");

    model::FoldPlan plan = model::defaultFoldPlan(*node, static_cast<std::size_t>(*count));
    if (product)
        plan.productNumber = product->toStdString();
    const auto config = model::buildPlcConfig(plan);
    if (!config.ok()) // an impossible plan is a usage error that says why
        return ctx.fail(kExitUsage,
                        "fold plan: " + model::plcText(config.error(), lang).toStdString());

    if (ctx.json)
        ctx.out << planJson(*config, plan, lang).dump(2) << '\n';
    else
        ctx.out << model::foldSheetText(*config, plan, lang).toStdString();
    return kExitOk;
}

} // namespace

int runFold(const QStringList &argsIn, Context &ctx)
{
    QStringList rest = argsIn;
    if (takeFlag(rest, "--help")) {
        ctx.out << kUsage << '\n';
        return kExitOk;
    }
    if (rest.isEmpty())
        return ctx.fail(kExitUsage, "fold: give a subcommand: plan (see fold --help)");
    const QString sub = rest.takeFirst();
    if (sub == "plan")
        return runPlan(rest, ctx);
    return ctx.fail(kExitUsage,
                    "fold: unknown subcommand '" + sub.toStdString() + "' (see fold --help)");
}

} // namespace vt::cli
