#include "fold_node_check.h"

#include <algorithm>
#include <string>

namespace vt::model {
namespace {

dev::LocalText number(int n)
{
    return dev::same(std::to_string(n));
}

} // namespace

std::optional<FoldNode> foldNodeOfFamily(std::string_view family)
{
    // Dictionary families: "opat", "dma-pb-v15" … "dma-pn-v51" (resources/dictionaries).
    for (FoldNode node : {FoldNode::Opat, FoldNode::DmaProfibus, FoldNode::DmaProfinet})
        if (family.substr(0, foldNodeKey(node).size()) == foldNodeKey(node))
            return node;
    return std::nullopt;
}

FoldPlan foldPlanFromNode(FoldPlan plan, std::vector<FoldNodeModule> node)
{
    std::sort(node.begin(), node.end(), [](const FoldNodeModule &a, const FoldNodeModule &b) {
        return a.address < b.address;
    });
    std::vector<FoldModule> modules = defaultFoldPlan(plan.node, node.size()).modules;
    for (std::size_t i = 0; i < modules.size(); ++i) {
        modules[i].version = node[i].version;
        modules[i].mode = node[i].mode;
        modules[i].address = node[i].address;
        if (i < plan.modules.size()) {
            modules[i].options = plan.modules[i].options;
            modules[i].name = plan.modules[i].name;
        }
    }
    plan.modules = std::move(modules);
    return plan;
}

std::vector<FoldFinding> checkPlanAgainstNode(const FoldPlan &plan,
                                              const std::vector<FoldNodeModule> &node)
{
    std::vector<FoldFinding> out;
    for (std::size_t i = 0; i < plan.modules.size(); ++i) {
        const FoldModule &m = plan.modules[i];
        const auto found = std::find_if(node.begin(), node.end(), [&](const FoldNodeModule &n) {
            return n.address == m.address;
        });
        const int module = static_cast<int>(i);
        if (found == node.end()) {
            out.push_back({FoldSeverity::Warning,
                           FoldCheckCode::NodeMismatch,
                           module,
                           {},
                           {{FoldText::NodeMissing, {number(module + 1), number(m.address)}}}});
        } else if ((m.version != 0 && m.version != found->version) ||
                   (m.mode != 0 && m.mode != found->mode)) {
            // A warning, not an error: the plan may be meant for the node as it will be after
            // the modules are exchanged; Apply then reports each module it cannot reach.
            out.push_back({FoldSeverity::Warning,
                           FoldCheckCode::NodeMismatch,
                           module,
                           {},
                           {{FoldText::NodeDiffers,
                             {number(module + 1), number(m.address), number(m.version),
                              number(m.mode), number(found->version), number(found->mode)}}}});
        }
    }
    for (const FoldNodeModule &n : node) {
        const bool planned =
            std::any_of(plan.modules.begin(), plan.modules.end(),
                        [&](const FoldModule &m) { return m.address == n.address; });
        if (!planned)
            out.push_back(
                {FoldSeverity::Warning,
                 FoldCheckCode::NodeMismatch,
                 -1,
                 {},
                 {{FoldText::NodeExtra, {number(n.address), number(n.version), number(n.mode)}}}});
    }
    return out;
}

} // namespace vt::model
