#include "model/fold/fold_plan.h"

#include <QCoreApplication>
#include <QString>

namespace vt::model {
namespace {

struct FoldPlanText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::FoldPlan)
};

} // namespace

QString foldNodeTitle(FoldNode node)
{
    switch (node) {
    case FoldNode::Opat: return FoldPlanText::tr("OPAT PROFIBUS master with CAN slaves");
    case FoldNode::DmaProfibus: return FoldPlanText::tr("DMA-2 modules on a PROFIBUS node");
    case FoldNode::DmaProfinet: return FoldPlanText::tr("DMA-2 modules on a PROFINET node");
    }
    return {};
}

QString foldAddressText(const FoldAddress &address)
{
    if (address.node != FoldNode::Opat)
        return FoldPlanText::tr("E22 = %1").arg(address.address);
    // OPAT manual §1.4: the master is SADR 0; a CAN slave's SADR is its rotary switch.
    if (address.address == 0)
        return FoldPlanText::tr("SADR 0 (master)");
    return FoldPlanText::tr("SADR %1 (rotary switch %1)").arg(address.address);
}

QString foldAddressText(FoldNode node, const FoldModule &module)
{
    return foldAddressText(foldAddress(node, module));
}

} // namespace vt::model
