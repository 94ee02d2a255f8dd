// The fold plan against the connected node: what each address of the node reported when the
// wizard read it (software version and mode, as a scan identifies them), and the findings where
// the plan does not match — a plan for V15 mode 1 applied to a V22 module would write options
// and hand the PLC an image for a module that is not there. Qt-free like the other checks.
#pragma once

#include "fold_check.h"

#include <optional>
#include <string_view>
#include <vector>

namespace vt::model {

struct FoldNodeModule
{
    int address = 0; // E22 / SADR
    int version = 0; // software major version
    int mode = 0;    // E00

    bool operator==(const FoldNodeModule &) const = default;
};

// The node type a module's dictionary family belongs to ("dma-pn-v51" → DmaProfinet, "opat" →
// Opat); nullopt for a device that is no fold module (Wandfluh).
std::optional<FoldNode> foldNodeOfFamily(std::string_view family);

// The node as read: `plan` with one module per answering address, in address order, each with the
// version, mode and address it reported. Options and names of `plan` stay with the module at the
// same position; the node type stays plan.node. Used by the scan and when the wizard opens on a
// connected node, so its pages start from the modules really there, not from a default plan.
FoldPlan foldPlanFromNode(FoldPlan plan, std::vector<FoldNodeModule> node);

// Findings with code NodeMismatch (warnings): a planned module whose address does not answer or
// answers with another version or mode, and a node module the plan leaves out.
std::vector<FoldFinding> checkPlanAgainstNode(const FoldPlan &plan,
                                              const std::vector<FoldNodeModule> &node);

} // namespace vt::model
