// foldSheetText: the plain-text PLC sheet printed by `valvetune-cli fold plan`.
#include "core/hex.h"
#include "fold_export.h"

#include <cstdio>

namespace vt::model {

using dev::Language;
using dev::LocalText;

namespace {

std::string pad(std::string s, std::size_t width)
{
    // Width in characters, not bytes: count UTF-8 lead bytes only.
    std::size_t chars = 0;
    for (char c : s)
        if ((static_cast<unsigned char>(c) & 0xC0u) != 0x80u)
            ++chars;
    if (chars < width)
        s.append(width - chars, ' ');
    return s;
}

std::string num(int v, int width)
{
    char buf[16];
    std::snprintf(buf, sizeof buf, "%*d", width, v);
    return buf;
}

std::string hex2(unsigned v)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", v & 0xFFu);
    return buf;
}

std::string byteLine(const PlcImageByte &b, Language lang)
{
    return "  " + num(b.offset, 4) + "  " + pad(b.field, 9) + b.text.in(lang) + "\n";
}

} // namespace

QString foldSheetText(const PlcConfig &c, const FoldPlan &plan, Language lang)
{
    const auto t = [lang](const char *en, const char *de) {
        return std::string(lang == Language::German ? de : en);
    };
    std::string o;
    o += t("Fold plan: ", "Modulplan: ") + foldNodeTitle(c.node).in(lang) + " (" +
         std::string(foldNodeKey(c.node)) + "), " + std::to_string(c.modules) +
         t(c.modules == 1 ? " module" : " modules", c.modules == 1 ? " Modul" : " Module") + "\n";
    if (!plan.title.empty())
        o += pad(t("Title:", "Titel:"), 13) + plan.title + "\n";
    o += pad(t("GSD file:", "GSD-Datei:"), 13) + c.gsdFile + "\n";
    o += pad(t("Device:", "Gerät:"), 13) + c.gsdDevice + "\n";
    o += pad(t("GSD module:", "GSD-Modul:"), 13) + c.gsdModule + "\n";
    o += pad(t("Output:", "Ausgang:"), 13) + std::to_string(c.outputBytes) +
         t(" bytes (PLC to node, CMD 15 request, SNUM = ",
           " Byte (SPS zum Knoten, CMD-15-Anfrage, SNUM = ") +
         std::to_string(c.snum) + ")\n";
    o += pad(t("Input:", "Eingang:"), 13) + std::to_string(c.inputBytes) +
         t(" bytes (node to PLC, one module per answer)",
           " Byte (Knoten zur SPS, ein Modul je Antwort)") +
         "\n";
    if (c.moduleOutputBytes != c.outputBytes || c.moduleInputBytes != c.inputBytes)
        o += pad(t("Reserved:", "Reserviert:"), 13) + std::to_string(c.moduleOutputBytes) + " / " +
             std::to_string(c.moduleInputBytes) +
             t(" bytes out / in by the GSD module", " Byte aus / ein durch das GSD-Modul") + "\n";
    o += pad(t("Source:", "Quelle:"), 13) + c.gsdNote.in(lang) + "\n";

    o += "\n" + t("Output image (PLC to node)", "Ausgangsabbild (SPS zum Knoten)") + "\n";
    o += "  " + pad(t("byte", "Byte"), 4) + "  " + pad(t("field", "Feld"), 9) +
         t("meaning", "Bedeutung") + "\n";
    for (const PlcImageByte &b : c.output)
        if (b.module < 0)
            o += byteLine(b, lang);
    for (const PlcModuleSection &s : c.sections) {
        const FoldModule *m = s.module < static_cast<int>(plan.modules.size())
                                  ? &plan.modules[static_cast<std::size_t>(s.module)]
                                  : nullptr;
        const auto &info = dev::hcs::profileInfo(s.profile);
        o += t("Module ", "Modul ") + std::to_string(s.module + 1);
        if (m) {
            o += " (" + foldAddressText(c.node, *m).in(lang);
            if (!m->name.empty())
                o += ", " + m->name;
            o += ")";
        }
        o += ": " + info.title.in(lang) + ", " + t("output bytes ", "Ausgangsbytes ") +
             std::to_string(s.outputFirst) + ".." +
             std::to_string(s.outputFirst + s.outputLength - 1) + "\n";
        for (const PlcImageByte &b : c.output)
            if (b.module == s.module)
                o += byteLine(b, lang);
        o += "        " + t("answer with SADR = ", "Antwort mit SADR = ") + std::to_string(s.sadr) +
             ": VALUE1 = " + std::string(info.response1.parameter) + " " +
             info.response1.text.in(lang) + "; VALUE2 = " + std::string(info.response2.parameter) +
             " " + info.response2.text.in(lang) + "\n";
        std::string bits;
        for (const auto &bit : s.controlBits)
            if (bit.used)
                bits += (bits.empty() ? "" : ", ") + hex2(bit.mask) + " " + std::string(bit.name);
        o += "        " + t("control byte bits: ", "Steuerbyte-Bits: ") +
             (bits.empty() ? "-" : bits) + "\n";
        bits.clear();
        for (const auto &bit : s.statusHighBits)
            if (bit.used)
                bits += (bits.empty() ? "" : ", ") + hex2(bit.mask) + " " + std::string(bit.name);
        o += "        " + t("status high byte: ", "Status High-Byte: ") +
             (bits.empty() ? "-" : bits) + "\n";
        bits.clear();
        for (const auto &bit : s.statusLowBits)
            if (bit.used)
                bits += (bits.empty() ? "" : ", ") + hex2(bit.mask) + " " + std::string(bit.name);
        o += "        " + t("status low byte: ", "Status Low-Byte: ") +
             (bits.empty()
                  ? t("no signals in this mode (error number while ERROR is set)",
                      "keine Signale in diesem Modus (Fehlernummer solange ERROR gesetzt ist)")
                  : bits + t(" (error number while ERROR is set)",
                             " (Fehlernummer solange ERROR gesetzt ist)")) +
             "\n";
    }

    o += "\n" +
         t("Input image (node to PLC, multiplexed: SADR names the module)",
           "Eingangsabbild (Knoten zur SPS, gemultiplext: SADR nennt das Modul)") +
         "\n";
    for (const PlcImageByte &b : c.input)
        o += byteLine(b, lang);

    o += "\n" +
         t("Example CMD 15 telegram (TADR 0x01, control byte 0x00, VALUE1 = 1000 = 1.000 V, VALUE2 "
           "= 0 for every module):",
           "Beispiel CMD-15-Telegramm (TADR 0x01, Steuerbyte 0x00, VALUE1 = 1000 = 1,000 V, VALUE2 "
           "= 0 für jedes Modul):") +
         "\n  " + dev::toHex(c.exampleRequestBytes) + "\n";
    return QString::fromStdString(o);
}

} // namespace vt::model
