#include "model/fold/module_guide.h"

#include <QCoreApplication>

namespace vt::model {

namespace {

class Guide
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::ModuleGuide)

public:
    static QString moduleAddress(const FoldPlan &plan, std::size_t index)
    {
        const FoldModule &m = plan.modules[index];
        const int n = static_cast<int>(index + 1);
        if (plan.node == FoldNode::Opat) {
            if (index == 0)
                return m.address == 0
                           ? tr("Module %1 (OPAT master, PROFIBUS interface): SADR %2, fixed; no "
                                "switch to set.")
                                 .arg(n)
                                 .arg(m.address)
                           : tr("Module %1 (OPAT master, PROFIBUS interface): SADR %2 — the "
                                "master must have SADR 0.")
                                 .arg(n)
                                 .arg(m.address);
            return tr("Module %1 (OPAT CAN slave): set the rotary switch to %2 (SADR %2).")
                .arg(n)
                .arg(m.address);
        }
        QString text = index == 0 ? tr("Module %1 (leftmost): E22 = %2.").arg(n).arg(m.address)
                                  : tr("Module %1: E22 = %2.").arg(n).arg(m.address);
        if (m.address > 5)
            text += QLatin1Char(' ') + tr("CMD 15 does not reach it; only CMD 3 / CMD 6.");
        return text;
    }

    static QString nodeRule(FoldNode node)
    {
        if (node == FoldNode::Opat)
            return tr("The first module, the one with the PROFIBUS interface, is the OPAT master "
                      "and always has SADR 0. The CAN slaves get SADR 1 to 7 only by their rotary "
                      "switch; no parameter changes it. Two slaves on the same switch position "
                      "stop the node (exception 12). (OPAT manual §1.4, §3.1)");
        return tr("Each DMA-2 module answers to its E22. Number them 1, 2, 3 … from the module on "
                  "the left to the one next to the bus node. CMD 15 reaches addresses 1 to 5 "
                  "only; modules with E22 above 5 (up to 32) are reachable with CMD 3 and CMD 6 "
                  "only. (DMA manuals §1.5, §4.1)");
    }

    static QString profibusNote(int e24)
    {
        const QString first =
            e24 == 126 ? tr("E24 = 126: the PROFIBUS master sets the address over the bus after "
                            "the next power-up; the address it gives then shows in E24.")
                       : tr("E24 = %1: the node's PROFIBUS address is %1; enter the same address "
                            "in the PLC's hardware configuration.")
                             .arg(e24);
        return first + QLatin1Char(' ') +
               tr("A change of E24 becomes active only after a power-down/power-up of the node.");
    }

    static QString cable(const FoldPlan &plan, std::size_t index)
    {
        const int n = static_cast<int>(index + 1);
        const int a = plan.modules[index].address;
        if (plan.node == FoldNode::Opat)
            return tr("Connect the service cable to module %1 (SADR %2), then press Next.")
                .arg(n)
                .arg(a);
        return tr("Connect the service cable to module %1 (E22 will become %2), then press Next.")
            .arg(n)
            .arg(a);
    }
};

} // namespace

QString moduleAddressGuide(const FoldPlan &plan, std::size_t index)
{
    return index < plan.modules.size() ? Guide::moduleAddress(plan, index) : QString();
}

QString nodeAddressRule(FoldNode node)
{
    return Guide::nodeRule(node);
}

QString profibusAddressNote(const FoldPlan &plan)
{
    if (plan.node != FoldNode::Opat || plan.modules.empty() || !plan.modules.front().options.e24)
        return {};
    return Guide::profibusNote(*plan.modules.front().options.e24);
}

QString cableGuide(const FoldPlan &plan, std::size_t index)
{
    return index < plan.modules.size() ? Guide::cable(plan, index) : QString();
}

} // namespace vt::model
