#include "model/fold/module_guide.h"

#include <string>

namespace vt::model {

namespace {

std::string number(std::size_t n)
{
    return std::to_string(n);
}

} // namespace

dev::LocalText moduleAddressGuide(const FoldPlan &plan, std::size_t index)
{
    if (index >= plan.modules.size())
        return {};
    const FoldModule &m = plan.modules[index];
    const std::string n = number(index + 1);
    const std::string a = std::to_string(m.address);
    if (plan.node == FoldNode::Opat) {
        if (index == 0)
            return {"Module " + n + " (OPAT master, PROFIBUS interface): SADR " + a +
                        (m.address == 0 ? ", fixed; no switch to set."
                                        : " — the master must have SADR 0."),
                    "Modul " + n + " (OPAT-Master, PROFIBUS-Schnittstelle): SADR " + a +
                        (m.address == 0 ? ", fest; kein Schalter einzustellen."
                                        : " — der Master muss SADR 0 haben.")};
        return {"Module " + n + " (OPAT CAN slave): set the rotary switch to " + a + " (SADR " + a +
                    ").",
                "Modul " + n + " (OPAT-CAN-Slave): Drehschalter auf " + a + " stellen (SADR " + a +
                    ")."};
    }
    const std::string where = index == 0 ? std::string(" (leftmost)") : std::string();
    const std::string wo = index == 0 ? std::string(" (ganz links)") : std::string();
    std::string en = "Module " + n + where + ": E22 = " + a + ".";
    std::string de = "Modul " + n + wo + ": E22 = " + a + ".";
    if (m.address > 5) {
        en += " CMD 15 does not reach it; only CMD 3 / CMD 6.";
        de += " CMD 15 erreicht es nicht, nur CMD 3 / CMD 6.";
    }
    return {en, de};
}

dev::LocalText nodeAddressRule(FoldNode node)
{
    if (node == FoldNode::Opat)
        return {
            "The first module, the one with the PROFIBUS interface, is the OPAT master and always "
            "has SADR 0. The CAN slaves get SADR 1 to 7 only by their rotary switch; no parameter "
            "changes it. Two slaves on the same switch position stop the node (exception 12). "
            "(OPAT manual §1.4, §3.1)",
            "Das erste Modul mit der PROFIBUS-Schnittstelle ist der OPAT-Master und hat immer SADR "
            "0. "
            "Die CAN-Slaves erhalten SADR 1 bis 7 nur über ihren Drehschalter; kein Parameter "
            "ändert "
            "ihn. Zwei Slaves mit derselben Schalterstellung legen den Knoten still (Exception "
            "12). "
            "(OPAT-Handbuch §1.4, §3.1)"};
    return {
        "Each DMA-2 module answers to its E22. Number them 1, 2, 3 … from the module on the left "
        "to the one next to the bus node. CMD 15 reaches addresses 1 to 5 only; modules with "
        "E22 above 5 (up to 32) are reachable with CMD 3 and CMD 6 only. (DMA manuals §1.5, §4.1)",
        "Jedes DMA-2-Modul antwortet auf seinen E22. Von links nach rechts 1, 2, 3 … bis zum Modul "
        "neben dem Busknoten nummerieren. CMD 15 erreicht nur die Adressen 1 bis 5; Module mit E22 "
        "über 5 (bis 32) sind nur mit CMD 3 und CMD 6 erreichbar. (DMA-Handbücher §1.5, §4.1)"};
}

dev::LocalText profibusAddressNote(const FoldPlan &plan)
{
    if (plan.node != FoldNode::Opat || plan.modules.empty() || !plan.modules.front().options.e24)
        return {};
    const int e24 = *plan.modules.front().options.e24;
    const std::string power =
        " A change of E24 becomes active only after a power-down/power-up of the node.";
    const std::string powerDe =
        " Eine Änderung von E24 wird erst nach Aus- und Wiedereinschalten des Knotens wirksam.";
    if (e24 == 126)
        return {"E24 = 126: the PROFIBUS master sets the address over the bus after the next "
                "power-up; the "
                "address it gives then shows in E24." +
                    power,
                "E24 = 126: Der PROFIBUS-Master vergibt die Adresse nach dem nächsten Einschalten "
                "über den "
                "Bus; sie erscheint danach in E24." +
                    powerDe};
    const std::string a = std::to_string(e24);
    return {"E24 = " + a + ": the node's PROFIBUS address is " + a +
                "; enter the same address in the PLC's "
                "hardware configuration." +
                power,
            "E24 = " + a + ": Die PROFIBUS-Adresse des Knotens ist " + a +
                "; dieselbe Adresse in der "
                "Hardware-Konfiguration der SPS eintragen." +
                powerDe};
}

dev::LocalText cableGuide(const FoldPlan &plan, std::size_t index)
{
    if (index >= plan.modules.size())
        return {};
    const std::string n = number(index + 1);
    const std::string a = std::to_string(plan.modules[index].address);
    if (plan.node == FoldNode::Opat)
        return {"Connect the service cable to module " + n + " (SADR " + a + "), then press Next.",
                "Das Servicekabel an Modul " + n + " (SADR " + a +
                    ") anschließen, dann Weiter drücken."};
    return {"Connect the service cable to module " + n + " (E22 will become " + a +
                "), then press Next.",
            "Das Servicekabel an Modul " + n + " (E22 wird " + a +
                ") anschließen, dann Weiter drücken."};
}

} // namespace vt::model
