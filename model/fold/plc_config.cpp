#include "plc_config.h"

#include <algorithm>
#include <cctype>

namespace vt::model {

using dev::LocalText;
namespace hcs = dev::hcs;

namespace {

std::string str(int value)
{
    return std::to_string(value);
}

LocalText num(int value)
{
    return dev::same(std::to_string(value));
}

PlcText valueText(const char *which, bool high, const hcs::ValueMeaning &meaning)
{
    // "VALUE1 high byte: A1.01 set value input (bus) (branch 1)"
    if (meaning.parameter.empty())
        return {high ? PlcTextId::ValueHigh : PlcTextId::ValueLow,
                {dev::same(which), meaning.text}};
    return {high ? PlcTextId::ValueHighParameter : PlcTextId::ValueLowParameter,
            {dev::same(which), dev::same(std::string(meaning.parameter)), meaning.text}};
}

// DMA Profibus Anleitung §6.1.1: "Die letzten beiden Ziffern der Produktnummer sind relevant.
// 5 xxx xxx x1 to x4 → hcs0220.gsd; 5 005 xxx x5 → hcs0ea7.gsd". Returns the last digit of a
// nine-digit number starting with 5, or nullopt.
std::optional<int> productVariant(const std::string &productNumber)
{
    std::string digits;
    for (char c : productNumber) {
        if (std::isdigit(static_cast<unsigned char>(c)))
            digits.push_back(c);
        else if (c != ' ' && c != '-' && c != '.')
            return std::nullopt;
    }
    if (digits.size() != 9 || digits.front() != '5')
        return std::nullopt;
    return digits.back() - '0';
}

} // namespace

GsdChoice chooseGsd(FoldNode node, std::size_t modules, const std::string &productNumber)
{
    GsdChoice g;
    const int n = static_cast<int>(modules);
    const int out = static_cast<int>(hcs::kCyclicHeaderSize + hcs::kCyclicModuleSize * modules);
    const int in = static_cast<int>(hcs::kCyclicResponseSize);
    switch (node) {
    case FoldNode::Opat:
        // OPAT manual §1.1 "Used GSD File HCS0D68.GSD"; §4.1: catalogue "OPAT - Profibus", modules
        // "CMD15 1M IN/OUT 9/8", "CMD15 1M 1S …" … "CMD15 1M 7S …"; example with 4 slaves: "CMD15
        // 1M 4S IN/OUT 9/28", output buffer at least 28 bytes, input at least 9.
        g.file = "HCS0D68.GSD";
        g.device = "OPAT - Profibus";
        g.module =
            n <= 1 ? "CMD15 1M IN/OUT 9/8" : "CMD15 1M " + str(n - 1) + "S IN/OUT 9/" + str(out);
        g.moduleOutputBytes = out;
        g.moduleInputBytes = in;
        g.note = {PlcTextId::OpatGsd, {num(std::max(n - 1, 0)), num(out)}};
        return g;
    case FoldNode::DmaProfinet:
        // DMA Profinet manual §1.1 "Used GSDML File"; §4.5.4: "select the IN/OUT 42 byte Rev…
        // module … So all kind of DMA module configuration can be processed."
        g.file = "GSDML-V2.2-HCS-DMA-XX_PN-….xml";
        g.device = "DMA-Profinet (Valves / DMA_DAC)";
        g.module = "IN/OUT 42 byte Rev…";
        g.moduleOutputBytes = 42;
        g.moduleInputBytes = 42;
        g.note = {PlcTextId::ProfinetGsd, {num(out)}};
        return g;
    case FoldNode::DmaProfibus: break;
    }

    const std::optional<int> variant = productVariant(productNumber);
    if (variant && *variant == 5) {
        // DMA Profibus Anleitung §6.1.1–6.1.4: "5 005 xxx x5 → hcs0ea7.gsd", device "DMA-22-XX",
        // module "TIA 28 Byte In / Output".
        g.file = "hcs0ea7.gsd";
        g.device = "DMA-22-XX";
        g.module = "TIA 28 Byte In / Output";
        g.moduleOutputBytes = 28;
        g.moduleInputBytes = 28;
        g.note = {PlcTextId::Ea7Gsd, {num(out)}};
        return g;
    }
    g.productNumberDecided = variant.has_value() && *variant >= 1 && *variant <= 4;
    // DMA Profibus Anleitung §1.1 "HCS0220.GSD"; §5.1: catalogue "DMA-2 - Profibus", modules
    // "CMD15 2fold 9B-I 13B-O (kons)" … "CMD15 5fold 9B-I 28B-O (kons)". The catalogue lists no
    // one-module CMD 15 entry; §5.1.1 sets lengths on the universal module instead.
    g.file = "HCS0220.GSD";
    g.device = "DMA-2 - Profibus";
    if (n >= 2) {
        g.module = "CMD15 " + str(n) + "fold 9B-I " + str(out) + "B-O (kons)";
        g.moduleOutputBytes = out;
        g.moduleInputBytes = in;
    } else {
        g.module =
            "Universalmodul: input 9 bytes, output 8 bytes, consistent over the whole length";
        g.moduleOutputBytes = out;
        g.moduleInputBytes = in;
    }
    const bool universal = n < 2; // §5.1.1: no one-module CMD 15 entry in the catalogue
    const PlcTextId note =
        universal
            ? (g.productNumberDecided ? PlcTextId::ProfibusGsdUniversal
                                      : PlcTextId::ProfibusGsdUniversalAssumed)
            : (g.productNumberDecided ? PlcTextId::ProfibusGsd : PlcTextId::ProfibusGsdAssumed);
    g.note = {note, {num(out)}};
    return g;
}

dev::Result<PlcConfig, PlcText> buildPlcConfig(const FoldPlan &plan)
{
    const std::size_t count = plan.modules.size();
    const hcs::Family family = foldFamily(plan.node);
    const std::size_t max = foldMaxCmd15Modules(plan.node);
    if (count == 0)
        return PlcText{PlcTextId::NoModules, {}};
    if (count > max)
        return PlcText{plan.node == FoldNode::Opat ? PlcTextId::TooManyOpat : PlcTextId::TooManyDma,
                       {num(static_cast<int>(count))}};

    PlcConfig c;
    c.node = plan.node;
    c.modules = static_cast<int>(count);
    c.snum = static_cast<int>(hcs::snumForModules(family, count).value_or(0));
    const GsdChoice gsd = chooseGsd(plan.node, count, plan.productNumber);
    c.gsdFile = gsd.file;
    c.gsdDevice = gsd.device;
    c.gsdModule = gsd.module;
    c.gsdNote = gsd.note;
    c.moduleOutputBytes = gsd.moduleOutputBytes;
    c.moduleInputBytes = gsd.moduleInputBytes;
    c.outputBytes = static_cast<int>(hcs::kCyclicHeaderSize + hcs::kCyclicModuleSize * count);
    c.inputBytes = static_cast<int>(hcs::kCyclicResponseSize);
    c.source = plan.node == FoldNode::Opat          ? "OPAT manual §1.4, §3.1–3.5, §4.1"
               : plan.node == FoldNode::DmaProfibus ? "DMA Profibus Anleitung §1.3, §4.1–4.5, §5–6"
                                                    : "DMA Profinet manual §1.3, §4.1–4.5, §5";

    // Request header (OPAT manual §3.1, DMA Profinet manual §4.1).
    const bool opat = plan.node == FoldNode::Opat;
    c.output.push_back({0, -1, "TADR", {PlcTextId::TadrOut, {}}});
    c.output.push_back(
        {1, -1, "SNUM", {opat ? PlcTextId::SnumOpat : PlcTextId::SnumDma, {num(c.snum)}}});
    c.output.push_back({2, -1, "CMD", {PlcTextId::CmdOut, {}}});

    c.exampleRequest.tadr = 0x01;
    for (std::size_t i = 0; i < count; ++i) {
        const FoldModule &m = plan.modules[i];
        const hcs::Profile profile =
            foldProfile(plan.node, m).value_or(hcs::defaultProfile(family));
        const hcs::ProfileInfo &info = hcs::profileInfo(profile);
        const int sadr = hcs::moduleAddress(family, i);
        const int first = static_cast<int>(hcs::kCyclicHeaderSize + hcs::kCyclicModuleSize * i);
        const int idx = static_cast<int>(i);
        const std::string dat = "DAT" + str(sadr);
        c.output.push_back({first, idx, dat + ".1", {PlcTextId::ControlByte, {}}});
        c.output.push_back({first + 1, idx, dat + ".2H", valueText("VALUE1", true, info.request1)});
        c.output.push_back(
            {first + 2, idx, dat + ".2L", valueText("VALUE1", false, info.request1)});
        c.output.push_back({first + 3, idx, dat + ".3H", valueText("VALUE2", true, info.request2)});
        c.output.push_back(
            {first + 4, idx, dat + ".3L", valueText("VALUE2", false, info.request2)});

        PlcModuleSection s;
        s.module = idx;
        s.sadr = sadr;
        s.profile = profile;
        s.outputFirst = first;
        s.outputLength = static_cast<int>(hcs::kCyclicModuleSize);
        s.controlBits = hcs::controlBits(profile);
        s.statusHighBits = hcs::statusHighBits(profile);
        s.statusLowBits = hcs::statusLowBits(profile);
        c.sections.push_back(s);

        // The manuals' worked examples write 1.000 V (1000) with the control byte 0x00 (OPAT manual
        // §3.4, DMA Profinet manual §4.4).
        c.exampleRequest.modules.push_back({0x00, 1000, 0});
    }

    // Response (OPAT manual §3.2, DMA Profinet manual §4.2): 9 bytes, multiplexed module by module.
    const std::string range =
        opat ? "0 … " + str(static_cast<int>(count) - 1) : "1 … " + str(static_cast<int>(count));
    c.input.push_back({0, -1, "TADR", {PlcTextId::TadrIn, {}}});
    c.input.push_back({1, -1, "SADR", {PlcTextId::SadrIn, {dev::same(range)}}});
    c.input.push_back({2, -1, "CMD", {PlcTextId::CmdIn, {}}});
    c.input.push_back({3, -1, "DAT.1H", {PlcTextId::StatusHigh, {}}});
    c.input.push_back({4, -1, "DAT.1L", {PlcTextId::StatusLow, {}}});
    // The value bytes of the module named by SADR; their meaning is listed per module.
    c.input.push_back({5, -1, "DAT.2H", {PlcTextId::AnswerHigh, {dev::same("VALUE1")}}});
    c.input.push_back({6, -1, "DAT.2L", {PlcTextId::AnswerLow, {dev::same("VALUE1")}}});
    c.input.push_back({7, -1, "DAT.3H", {PlcTextId::AnswerHigh, {dev::same("VALUE2")}}});
    c.input.push_back({8, -1, "DAT.3L", {PlcTextId::AnswerLow, {dev::same("VALUE2")}}});

    auto encoded = hcs::encode(c.exampleRequest, family);
    if (encoded.ok())
        c.exampleRequestBytes = *encoded;
    return c;
}

} // namespace vt::model
