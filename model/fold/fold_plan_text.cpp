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

} // namespace vt::model
