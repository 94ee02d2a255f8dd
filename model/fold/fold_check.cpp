#include "fold_check.h"

#include "dict/dictionary.h"
#include "dict/dictionary_loader.h"
#include "hcs/cmd15.h"
#include "plc_config.h"

#include <algorithm>
#include <map>
#include <set>

namespace vt::model {

using dev::LocalText;

namespace {

template<typename T> std::string str(T v)
{
    return std::to_string(v);
}

std::string moduleName(FoldNode node, std::size_t i, const FoldModule &m, dev::Language lang)
{
    const bool de = lang == dev::Language::German;
    std::string s = (de ? "Modul " : "Module ") + str(static_cast<long long>(i + 1)) + " (" +
                    foldAddressText(node, m).in(lang) + ")";
    return s;
}

// With the version unknown, the mode (or the family's worked example) picks the dictionary.
int effectiveVersion(FoldNode node, std::size_t index, const FoldModule &m)
{
    if (m.version != 0)
        return m.version;
    switch (node) {
    case FoldNode::Opat: return index == 0 ? 34 : 31;
    case FoldNode::DmaProfibus: return m.mode == 2 ? 22 : (m.mode >= 3 ? 32 : 15);
    case FoldNode::DmaProfinet: return m.mode >= 3 ? 51 : 13;
    }
    return 0;
}

class Checker
{
public:
    Checker(const FoldPlan &plan, const dev::DictionarySet *set) : m_plan(plan), m_set(set) {}

    std::vector<FoldFinding> run()
    {
        checkCount();
        checkProductNumber();
        checkAddresses();
        checkSnum();
        checkModes();
        for (std::size_t i = 0; i < m_plan.modules.size(); ++i)
            checkOptions(i);
        checkCanBaud();
        std::stable_sort(
            m_out.begin(), m_out.end(),
            [](const FoldFinding &a, const FoldFinding &b) { return a.module < b.module; });
        return m_out;
    }

private:
    void add(FoldSeverity s, FoldCheckCode c, int module, std::string param, LocalText text)
    {
        m_out.push_back({s, c, module, std::move(param), std::move(text)});
    }
    LocalText who(std::size_t i) const
    {
        const FoldModule &m = m_plan.modules[i];
        return {moduleName(m_plan.node, i, m, dev::Language::English),
                moduleName(m_plan.node, i, m, dev::Language::German)};
    }
    bool opat() const { return m_plan.node == FoldNode::Opat; }

    void checkCount()
    {
        const std::size_t n = m_plan.modules.size();
        if (n == 0) {
            add(FoldSeverity::Error, FoldCheckCode::NoModules, -1, {},
                {"The plan has no modules.", "Der Plan enthält keine Module."});
            return;
        }
        if (n > foldMaxModules(m_plan.node)) {
            add(FoldSeverity::Error, FoldCheckCode::TooManyModules, -1, {},
                opat()
                    ? LocalText{str(n) + " modules: an OPAT node has the master and at most 7 CAN "
                                         "slaves (rotary switch 1 … 7; OPAT manual §1.4).",
                                str(n) + " Module: Ein OPAT-Knoten hat den Master und höchstens 7 "
                                         "CAN-Slaves (Drehschalter 1 … 7; OPAT-Handbuch §1.4)."}
                    : LocalText{
                          str(n) +
                              " modules: a DMA node addresses at most 32 modules (E22 = 1 … 32; "
                              "DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).",
                          str(n) + " Module: Ein DMA-Knoten adressiert höchstens 32 Module "
                                   "(E22 = 1 … 32; DMA Profibus Anleitung §1.5, "
                                   "DMA-Profinet-Handbuch §1.5)."});
            return;
        }
        if (!opat() && n > foldMaxCmd15Modules(m_plan.node))
            add(FoldSeverity::Error, FoldCheckCode::Cmd15Limit, -1, {},
                {str(n) + " DMA modules: CMD 15 reaches E22 = 1 … 5 only. Modules above 5 can be "
                          "reached by CMD 3 / CMD 6 only and cannot be part of the cyclic PLC "
                          "image (DMA Profibus "
                          "Anleitung §1.5, DMA Profinet manual §1.5). Plan at most 5 modules for "
                          "CMD 15.",
                 str(n) +
                     " DMA-Module: CMD 15 erreicht nur E22 = 1 … 5. Module über 5 sind nur mit "
                     "CMD 3 / CMD 6 erreichbar und können nicht Teil des zyklischen SPS-Abbilds "
                     "sein (DMA "
                     "Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5). Für CMD 15 höchstens 5 "
                     "Module planen."});
    }

    void checkProductNumber()
    {
        if (m_plan.node != FoldNode::DmaProfibus || m_plan.modules.empty())
            return;
        const GsdChoice g = chooseGsd(m_plan.node, m_plan.modules.size(), m_plan.productNumber);
        if (g.productNumberDecided)
            return;
        const bool given = !m_plan.productNumber.empty();
        add(given ? FoldSeverity::Warning : FoldSeverity::Info, FoldCheckCode::ProductNumber, -1,
            {},
            {std::string(given ? "The product number \"" + m_plan.productNumber +
                                     "\" does not decide the GSD file"
                               : "No product number given") +
                 ": HCS0220.GSD is assumed. Product numbers 5 xxx xxx x1 … x4 use hcs0220.gsd, "
                 "5 005 xxx x5 use hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).",
             std::string(given ? "Die Produktnummer \"" + m_plan.productNumber +
                                     "\" legt die GSD-Datei nicht fest"
                               : "Keine Produktnummer angegeben") +
                 ": HCS0220.GSD wird angenommen. Produktnummern 5 xxx xxx x1 … x4 verwenden "
                 "hcs0220.gsd, "
                 "5 005 xxx x5 verwenden hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1)."});
    }

    void checkAddresses()
    {
        const std::size_t n = m_plan.modules.size();
        std::map<int, std::vector<std::size_t>> byAddress;
        bool allInRange = true;
        for (std::size_t i = 0; i < n; ++i) {
            const FoldModule &m = m_plan.modules[i];
            const int idx = static_cast<int>(i);
            byAddress[m.address].push_back(i);
            if (opat()) {
                if (i == 0 && m.address != 0) {
                    add(FoldSeverity::Error, FoldCheckCode::AddressOrder, idx, "SADR",
                        {"The first module (the one with the PROFIBUS interface) must always have "
                         "SADR = 0 "
                         "(OPAT manual §1.4).",
                         "Das erste Modul (das mit der PROFIBUS-Schnittstelle) muss immer SADR = 0 "
                         "haben "
                         "(OPAT-Handbuch §1.4)."});
                    allInRange = false;
                } else if (i > 0 && (m.address < 1 || m.address > 7)) {
                    add(FoldSeverity::Error, FoldCheckCode::AddressOutOfRange, idx, "SADR",
                        who(i).en.empty()
                            ? LocalText{}
                            : LocalText{who(i).en + ": CAN slaves take rotary switch positions 1 … "
                                                    "7 only (OPAT manual §1.4, §3.1).",
                                        who(i).de +
                                            ": CAN-Slaves haben nur die Drehschalterstellungen 1 … "
                                            "7 (OPAT-Handbuch §1.4, §3.1)."});
                    allInRange = false;
                }
                continue;
            }
            // DMA: E22 range from the dictionary (0 = no bus function … 32).
            if (m.address < 1 || m.address > 32) {
                add(FoldSeverity::Error, FoldCheckCode::AddressOutOfRange, idx, "E22",
                    m.address == 0 ? LocalText{who(i).en + ": E22 = 0 switches the module's bus "
                                                           "function off; the node "
                                                           "cannot reach it.",
                                               who(i).de + ": E22 = 0 schaltet die Busfunktion des "
                                                           "Moduls ab; der Knoten "
                                                           "erreicht es nicht."}
                                   : LocalText{who(i).en + ": E22 must be 1 … 32.",
                                               who(i).de + ": E22 muss 1 … 32 sein."});
                allInRange = false;
            } else if (m.address > 5) {
                add(FoldSeverity::Error, FoldCheckCode::AddressBeyondCmd15, idx, "E22",
                    {who(i).en +
                         ": CMD 15 reaches E22 = 1 … 5 only; this module is reachable by CMD 3 / "
                         "CMD 6 only (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).",
                     who(i).de +
                         ": CMD 15 erreicht nur E22 = 1 … 5; dieses Modul ist nur mit CMD 3 / CMD "
                         "6 "
                         "erreichbar (DMA Profibus Anleitung §1.5, DMA-Profinet-Handbuch §1.5)."});
                allInRange = false;
            }
        }
        for (const auto &[address, indices] : byAddress) {
            if (indices.size() < 2)
                continue;
            std::string list;
            for (std::size_t k : indices)
                list += (list.empty() ? "" : ", ") + str(static_cast<long long>(k + 1));
            const std::string a = str(address);
            add(FoldSeverity::Error, FoldCheckCode::DuplicateAddress, static_cast<int>(indices[1]),
                opat() ? "SADR" : "E22",
                opat() ? LocalText{"Modules " + list + " share SADR " + a +
                                       ": the red LED lights and the master "
                                       "reports exception 12 \"two or more slaves have the same "
                                       "slave address\" "
                                       "(OPAT manual §1.3.2, §3.3). Set a different rotary switch "
                                       "position.",
                                   "Module " + list + " haben dieselbe SADR " + a +
                                       ": Die rote LED leuchtet und "
                                       "der Master meldet Exception 12 \"zwei oder mehr Slaves "
                                       "haben dieselbe "
                                       "Adresse\" (OPAT-Handbuch §1.3.2, §3.3). Anderen "
                                       "Drehschalter-Wert einstellen."}
                       : LocalText{"Modules " + list + " share E22 = " + a +
                                       ": the node cannot tell them apart. "
                                       "Set E22 = 1 … n from left to right (DMA Profibus Anleitung "
                                       "§1.3, DMA Profinet "
                                       "manual §1.3).",
                                   "Module " + list + " haben dasselbe E22 = " + a +
                                       ": Der Knoten kann sie nicht "
                                       "unterscheiden. E22 = 1 … n von links nach rechts setzen "
                                       "(DMA Profibus "
                                       "Anleitung §1.3, DMA-Profinet-Handbuch §1.3)."});
            allInRange = false;
        }
        if (!allInRange || n == 0 || n > foldMaxCmd15Modules(m_plan.node))
            return;
        // CMD 15 block x goes to the module with address x, SNUM covers 1 … n (0 … n−1 on OPAT).
        const int base = opat() ? 0 : 1;
        bool gap = false, rising = true;
        for (std::size_t i = 0; i < n; ++i) {
            const int a = m_plan.modules[i].address;
            if (a - base >= static_cast<int>(n))
                gap = true;
            if (a != base + static_cast<int>(i))
                rising = false;
        }
        if (gap) {
            const std::string want = opat() ? "0 … " + str(static_cast<long long>(n) - 1)
                                            : "1 … " + str(static_cast<long long>(n));
            add(FoldSeverity::Error, FoldCheckCode::AddressOrder, -1, opat() ? "SADR" : "E22",
                {"With " + str(static_cast<long long>(n)) + " modules CMD 15 addresses " + want +
                     "; a module outside that range gets no set values and the node answers "
                     "exception 8 "
                     "\"timeout slave, address wrong or not installed\" (OPAT manual §3.3, DMA "
                     "Profinet manual §4.3).",
                 "Mit " + str(static_cast<long long>(n)) + " Modulen adressiert CMD 15 " + want +
                     "; ein Modul außerhalb erhält keine Sollwerte und der Knoten antwortet mit "
                     "Exception 8 "
                     "\"Timeout Slave, Adresse falsch oder nicht installiert\" (OPAT-Handbuch "
                     "§3.3, "
                     "DMA-Profinet-Handbuch §4.3)."});
        } else if (!rising) {
            add(FoldSeverity::Warning, FoldCheckCode::AddressOrder, -1, opat() ? "SADR" : "E22",
                opat()
                    ? LocalText{"Set the slaves' rotary switches in rising, consecutive order "
                                "beginning with 1 "
                                "(OPAT manual §1.6).",
                                "Die Drehschalter der Slaves aufsteigend und lückenlos ab 1 "
                                "einstellen "
                                "(OPAT-Handbuch §1.6)."}
                    : LocalText{
                          "Set E22 = 1 for the module on the left, rising towards the node module "
                          "(DMA Profibus Anleitung §1.3, DMA Profinet manual §1.3, §4.1).",
                          "E22 = 1 für das linke Modul setzen, aufsteigend zum Knotenmodul hin "
                          "(DMA Profibus Anleitung §1.3, DMA-Profinet-Handbuch §1.3, §4.1)."});
        }
    }

    void checkSnum()
    {
        if (!m_plan.plcSnum || m_plan.modules.empty())
            return;
        const auto family = foldFamily(m_plan.node);
        const auto want = dev::hcs::snumForModules(family, m_plan.modules.size());
        const int have = *m_plan.plcSnum;
        if (want && have == *want)
            return;
        const std::string n = str(static_cast<long long>(m_plan.modules.size()));
        const std::string w = want ? str(*want) : "-";
        const std::string h = str(have);
        const auto max = dev::hcs::maxCyclicModules(family);
        const bool invalid = !dev::hcs::modulesForSnum(
                                 family, static_cast<std::uint8_t>(std::clamp(have, 0, 255))) ||
                             have < 0 || have > 255;
        LocalText t =
            opat() ? LocalText{"The PLC sends SNUM = " + h + " but the node has " + n +
                                   " modules (master + " + w + " slaves → SNUM = " + w + ").",
                               "Die SPS sendet SNUM = " + h + ", der Knoten hat aber " + n +
                                   " Module (Master + " + w + " Slaves → SNUM = " + w + ")."}
                   : LocalText{"The PLC sends SNUM = " + h + " but the node has " + n +
                                   " modules (SNUM = " + w + ").",
                               "Die SPS sendet SNUM = " + h + ", der Knoten hat aber " + n +
                                   " Module (SNUM = " + w + ")."};
        if (invalid) {
            t.en += " An SNUM outside " + std::string(opat() ? "0 … 7" : "1 … 5") +
                    " is answered with exception 7 "
                    "\"invalid number of connected slaves\".";
            t.de += " Eine SNUM außerhalb " + std::string(opat() ? "0 … 7" : "1 … 5") +
                    " wird mit Exception 7 "
                    "\"ungültige Anzahl angeschlossener Slaves\" beantwortet.";
        } else if (want && have > *want) {
            t.en += " The node then waits for modules that are not installed: exception 8 "
                    "\"timeout slave, "
                    "address wrong or not installed\".";
            t.de += " Der Knoten wartet dann auf nicht installierte Module: Exception 8 \"Timeout "
                    "Slave, "
                    "Adresse falsch oder nicht installiert\".";
        } else {
            t.en += " The modules beyond SNUM get no set values and never answer.";
            t.de += " Die Module jenseits von SNUM erhalten keine Sollwerte und antworten nie.";
        }
        t.en += " SNUM also fixes the telegram length (3 + 5 bytes per module, up to " +
                str(static_cast<long long>(3 + 5 * max)) +
                "); a GSD module that is too short gives exception 9 (OPAT manual §3.1, §3.3; DMA "
                "Profinet manual §4.1).";
        t.de += " SNUM legt auch die Telegrammlänge fest (3 + 5 Byte je Modul, bis " +
                str(static_cast<long long>(3 + 5 * max)) +
                "); ein zu kurzes GSD-Modul ergibt Exception 9 (OPAT-Handbuch §3.1, §3.3; "
                "DMA-Profinet-Handbuch §4.1).";
        add(FoldSeverity::Error, FoldCheckCode::SnumMismatch, -1, "SNUM", t);
    }

    void checkModes()
    {
        std::set<int> profiles;
        for (std::size_t i = 0; i < m_plan.modules.size(); ++i) {
            const FoldModule &m = m_plan.modules[i];
            const int idx = static_cast<int>(i);
            const std::vector<int> versions = foldVersions(m_plan.node, i);
            if (m.version == 0) {
                add(FoldSeverity::Info, FoldCheckCode::UnknownVersion, idx, "Vers",
                    {who(i).en + ": software version not known; the layout of the manuals' worked "
                                 "examples is assumed. "
                                 "Scan the node to fill it in.",
                     who(i).de + ": Softwareversion unbekannt; das Layout der Beispiele der "
                                 "Handbücher wird angenommen. "
                                 "Den Knoten scannen, um sie einzutragen."});
            } else if (std::find(versions.begin(), versions.end(), m.version) == versions.end()) {
                std::string list;
                for (int v : versions)
                    list += (list.empty() ? "V" : ", V") + str(v);
                add(FoldSeverity::Error, FoldCheckCode::UnknownVersion, idx, "Vers",
                    {who(i).en + ": software V" + str(m.version) +
                         " does not belong here; the manual describes " + list +
                         " for this position.",
                     who(i).de + ": Software V" + str(m.version) +
                         " gehört nicht hierher; das Handbuch beschreibt " + list +
                         " für diese Position."});
                continue;
            }
            const auto profile = foldProfile(m_plan.node, m);
            if (!profile) {
                add(FoldSeverity::Error, FoldCheckCode::UnknownLayout, idx, "E00",
                    {who(i).en + ": the manuals define no CMD 15 layout for software V" +
                         str(m.version) + " in mode " + str(m.mode) + ".",
                     who(i).de + ": Die Handbücher definieren kein CMD-15-Layout für Software V" +
                         str(m.version) + " im Modus " + str(m.mode) + "."});
                continue;
            }
            profiles.insert(static_cast<int>(*profile));
        }
        if (profiles.size() > 1)
            add(FoldSeverity::Warning, FoldCheckCode::MixedModes, -1, "E00",
                {"The modules run in different modes or software versions. Only the control-byte "
                 "and status-word "
                 "bits of each module's own mode apply; the PLC must read VALUE1/VALUE2 per SADR "
                 "with that module's "
                 "meaning (DMA Profibus Anleitung §6, DMA Profinet manual §5).",
                 "Die Module arbeiten in verschiedenen Modi oder Softwareversionen. Nur die Bits "
                 "im Steuerbyte und "
                 "Statuswort entsprechend dem Modus des jeweiligen Moduls sind zu beachten; die "
                 "SPS muss VALUE1/VALUE2 "
                 "je SADR mit der Bedeutung dieses Moduls lesen (DMA Profibus Anleitung §6, "
                 "DMA-Profinet-Handbuch §5)."});
    }

    const dev::Dictionary *dictionaryFor(std::size_t i) const
    {
        if (!m_set)
            return nullptr;
        FoldModule m = m_plan.modules[i];
        m.version = effectiveVersion(m_plan.node, i, m);
        return foldDictionary(*m_set, m_plan.node, m);
    }

    void checkOptions(std::size_t i)
    {
        const FoldModule &m = m_plan.modules[i];
        const int idx = static_cast<int>(i);
        const std::vector<std::string> allowed = foldOptionNames(m_plan.node, i);
        const dev::Dictionary *dict = dictionaryFor(i);
        const std::string version = str(effectiveVersion(m_plan.node, i, m));
        for (const char *name : {"E17", "E23", "E24", "E26", "E28"}) {
            const std::optional<int> value = foldOption(m.options, name);
            if (!value)
                continue;
            if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
                add(FoldSeverity::Warning, FoldCheckCode::OptionNotApplicable, idx, name,
                    {who(i).en + ": " + name +
                         " is not a bus option of this module here; it is ignored.",
                     who(i).de + ": " + name +
                         " ist hier keine Busoption dieses Moduls; wird ignoriert."});
                continue;
            }
            const dev::ParamMeta *meta = dict ? dict->find(name) : nullptr;
            if (meta && !meta->appliesTo(version, "")) {
                add(FoldSeverity::Warning, FoldCheckCode::OptionNotApplicable, idx, name,
                    {who(i).en + ": " + name + " does not exist in software V" + version +
                         "; it is ignored.",
                     who(i).de + ": " + name + " gibt es in Software V" + version +
                         " nicht; wird ignoriert."});
                continue;
            }
            if (meta && (*value < meta->min || *value > meta->max)) {
                const std::string range = str(static_cast<long long>(meta->min)) + " … " +
                                          str(static_cast<long long>(meta->max));
                add(FoldSeverity::Error, FoldCheckCode::OptionOutOfRange, idx, name,
                    {who(i).en + ": " + name + " = " + str(*value) + " is outside " + range + " (" +
                         meta->label.en + ").",
                     who(i).de + ": " + name + " = " + str(*value) + " liegt außerhalb " + range +
                         " (" + meta->label.in(dev::Language::German) + ")."});
                continue;
            }
            consequence(i, name, *value);
        }
    }

    void consequence(std::size_t i, const std::string &name, int value)
    {
        const int idx = static_cast<int>(i);
        if (name == "E24") {
            add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, idx, name,
                value == 126
                    ? LocalText{"E24 = 126: the PROFIBUS master sets the address. Set it before "
                                "power-up; the "
                                "address the master assigns then shows in E24 (OPAT manual §1.4).",
                                "E24 = 126: Der PROFIBUS-Master vergibt die Adresse. Vor dem "
                                "Einschalten setzen; die "
                                "vom Master vergebene Adresse erscheint danach in E24 "
                                "(OPAT-Handbuch §1.4)."}
                    : LocalText{"E24 = " + str(value) +
                                    ": the new PROFIBUS address becomes active only after a "
                                    "power-down/power-up sequence (OPAT manual §1.4).",
                                "E24 = " + str(value) +
                                    ": Die neue PROFIBUS-Adresse wird erst nach Aus- und "
                                    "Wiedereinschalten aktiv (OPAT-Handbuch §1.4)."});
        } else if (name == "E28") {
            // OPAT manual §5.7: behaviour of the master when a CAN slave is lost.
            static const LocalText kText[] = {
                {"E28 = 0: a lost CAN slave gives error 7 and the master goes to the disabled "
                 "state "
                 "(OPAT manual §5.7).",
                 "E28 = 0: Ein ausgefallener CAN-Slave ergibt Fehler 7 und der Master geht in den "
                 "Zustand "
                 "gesperrt (OPAT-Handbuch §5.7)."},
                {"E28 = 1: a lost CAN slave sets the error bit, but the master remains in its "
                 "previous state "
                 "(OPAT manual §5.7).",
                 "E28 = 1: Ein ausgefallener CAN-Slave setzt das Fehlerbit, der Master bleibt aber "
                 "in seinem "
                 "bisherigen Zustand (OPAT-Handbuch §5.7)."},
                {"E28 = 2: error 7 is ignored; the master ignores lost CAN slaves, so a lost slave "
                 "goes "
                 "unnoticed by the PLC (OPAT manual §5.7).",
                 "E28 = 2: Fehler 7 wird ignoriert; der Master ignoriert ausgefallene CAN-Slaves, "
                 "die SPS "
                 "bemerkt einen Ausfall also nicht (OPAT-Handbuch §5.7)."}};
            add(value == 2 ? FoldSeverity::Warning : FoldSeverity::Info,
                FoldCheckCode::OptionConsequence, idx, name, kText[std::clamp(value, 0, 2)]);
        } else if (name == "E23" && value == 0) {
            add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, idx, name,
                {who(i).en + ": E23 = 0 switches the bus telegram timeout off; the module does not "
                             "react when the "
                             "PLC stops sending.",
                 who(i).de + ": E23 = 0 schaltet die Bus-Telegrammüberwachung ab; das Modul "
                             "reagiert nicht, wenn "
                             "die SPS keine Telegramme mehr sendet."});
        } else if (name == "E17" && value == 0) {
            add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, idx, name,
                {who(i).en + ": E17 = 0 keeps the analogue set value input active; set E17 = 2 "
                             "when the set "
                             "value comes from the bus only.",
                 who(i).de +
                     ": E17 = 0 lässt den analogen Sollwerteingang aktiv; E17 = 2 setzen, wenn der "
                     "Sollwert nur über den Bus kommt."});
        } else if (name == "E26") {
            if (value == 0 && m_plan.modules.size() > 1)
                add(FoldSeverity::Error, FoldCheckCode::OptionConsequence, idx, name,
                    {who(i).en + ": E26 = 0 disables CAN; the master cannot reach the slaves (OPAT "
                                 "manual §7).",
                     who(i).de + ": E26 = 0 sperrt CAN; der Master erreicht die Slaves nicht "
                                 "(OPAT-Handbuch §7)."});
        }
    }

    // Every OPAT module on the CAN bus must use the same baud rate; a change set through PROFIBUS
    // takes effect only after a reboot (OPAT manual §7, E26).
    void checkCanBaud()
    {
        if (!opat())
            return;
        std::set<int> rates;
        bool any = false;
        for (const FoldModule &m : m_plan.modules)
            if (m.options.e26) {
                rates.insert(*m.options.e26);
                any = true;
            }
        if (rates.size() > 1)
            add(FoldSeverity::Error, FoldCheckCode::OptionConsequence, -1, "E26",
                {"The modules are given different CAN baud rates (E26): master and slaves must use "
                 "the same rate "
                 "or the master loses its slaves (error 7, exception 5 \"timeout (CAN "
                 "connection)\").",
                 "Die Module haben verschiedene CAN-Baudraten (E26): Master und Slaves müssen "
                 "dieselbe Rate "
                 "verwenden, sonst verliert der Master seine Slaves (Fehler 7, Exception 5 "
                 "\"Timeout (CAN-Verbindung)\")."});
        else if (any)
            add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, -1, "E26",
                {"A CAN baud rate (E26) changed through PROFIBUS becomes active only after a "
                 "reboot (OPAT manual §7).",
                 "Eine über PROFIBUS geänderte CAN-Baudrate (E26) wird erst nach einem Neustart "
                 "aktiv (OPAT-Handbuch §7)."});
    }

    const FoldPlan &m_plan;
    const dev::DictionarySet *m_set;
    std::vector<FoldFinding> m_out;
};

} // namespace

std::vector<FoldFinding> checkFoldPlan(const FoldPlan &plan, const dev::DictionarySet *dictionaries)
{
    if (!dictionaries) {
        const auto &builtin = dev::builtinDictionaries();
        dictionaries = builtin.ok() ? &*builtin : nullptr;
    }
    return Checker(plan, dictionaries).run();
}

bool hasErrors(const std::vector<FoldFinding> &findings)
{
    return std::any_of(findings.begin(), findings.end(),
                       [](const FoldFinding &f) { return f.severity == FoldSeverity::Error; });
}

std::string_view foldSeverityKey(FoldSeverity severity)
{
    switch (severity) {
    case FoldSeverity::Info: return "info";
    case FoldSeverity::Warning: return "warning";
    case FoldSeverity::Error: return "error";
    }
    return "info";
}

LocalText foldSeverityText(FoldSeverity severity)
{
    switch (severity) {
    case FoldSeverity::Info: return {"Note", "Hinweis"};
    case FoldSeverity::Warning: return {"Warning", "Warnung"};
    case FoldSeverity::Error: return {"Error", "Fehler"};
    }
    return {};
}

} // namespace vt::model
