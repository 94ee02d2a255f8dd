#include "fold_plan.h"

#include "dict/dictionary.h"
#include "hcs/cmd15.h"

#include <algorithm>

namespace vt::model {

using dev::hcs::Family;

std::string_view foldNodeKey(FoldNode node)
{
    switch (node) {
    case FoldNode::Opat: return "opat";
    case FoldNode::DmaProfibus: return "dma-pb";
    case FoldNode::DmaProfinet: return "dma-pn";
    }
    return "dma-pb";
}

std::optional<FoldNode> foldNodeFromKey(std::string_view key)
{
    for (FoldNode node : {FoldNode::Opat, FoldNode::DmaProfibus, FoldNode::DmaProfinet})
        if (foldNodeKey(node) == key)
            return node;
    return std::nullopt;
}

Family foldFamily(FoldNode node)
{
    return node == FoldNode::Opat ? Family::Opat : Family::Dma;
}

std::size_t foldMaxCmd15Modules(FoldNode node)
{
    return dev::hcs::maxCyclicModules(foldFamily(node));
}

std::size_t foldMaxModules(FoldNode node)
{
    // DMA Profinet manual §1.5 / DMA Profibus Anleitung §1.5: "Theoretically up to 32 slaves".
    return node == FoldNode::Opat ? 8 : 32;
}

std::vector<int> foldVersions(FoldNode node, std::size_t moduleIndex)
{
    switch (node) {
    case FoldNode::Opat:
        // OPAT manual §1.2: V34 = Profibus slave and CAN master, V31 = CAN slave.
        return moduleIndex == 0 ? std::vector<int>{34} : std::vector<int>{31};
    case FoldNode::DmaProfibus: return {15, 22, 31, 32}; // DMA Profibus Anleitung §1.2
    case FoldNode::DmaProfinet: return {13, 51};         // DMA Profinet manual §1.2
    }
    return {};
}

FoldPlan defaultFoldPlan(FoldNode node, std::size_t modules)
{
    FoldPlan plan;
    plan.node = node;
    plan.modules.reserve(modules);
    for (std::size_t i = 0; i < modules; ++i) {
        FoldModule m;
        switch (node) {
        case FoldNode::Opat:
            m.version = i == 0 ? 34 : 31;
            m.mode = 3;
            m.address = static_cast<int>(i);
            break;
        case FoldNode::DmaProfibus:
            m.version = 15;
            m.mode = 1;
            m.address = static_cast<int>(i + 1);
            break;
        case FoldNode::DmaProfinet:
            m.version = 13;
            m.mode = 1;
            m.address = static_cast<int>(i + 1);
            break;
        }
        plan.modules.push_back(m);
    }
    return plan;
}

std::string foldDictionaryFamily(FoldNode node, const FoldModule &module)
{
    switch (node) {
    case FoldNode::Opat: return module.version == 34 || module.version == 31 ? "opat" : "";
    case FoldNode::DmaProfibus:
        switch (module.version) {
        case 15: return "dma-pb-v15";
        case 22: return "dma-pb-v22";
        case 31: // DMA Profibus Anleitung §1.2: V31 shares the V32 parameter set
        case 32: return "dma-pb-v32";
        default: return "";
        }
    case FoldNode::DmaProfinet:
        switch (module.version) {
        case 13: return "dma-pn-v13";
        case 51: return "dma-pn-v51";
        default: return "";
        }
    }
    return "";
}

const dev::Dictionary *foldDictionary(const dev::DictionarySet &set, FoldNode node,
                                      const FoldModule &module)
{
    const std::string family = foldDictionaryFamily(node, module);
    return family.empty() ? nullptr : set.find(family);
}

std::optional<dev::hcs::Profile> foldProfile(FoldNode node, const FoldModule &module)
{
    int version = module.version;
    // profileFor() tells DMA Profibus and Profinet apart by the version only; with the version
    // unknown, the node decides which worked example applies.
    if (version == 0 && node == FoldNode::DmaProfinet)
        version = module.mode == 3 || module.mode == 4 ? 51 : 13;
    if (node == FoldNode::DmaProfinet && version != 13 && version != 51)
        return std::nullopt;
    if (node == FoldNode::DmaProfibus && (version == 13 || version == 51))
        return std::nullopt;
    return dev::hcs::profileFor(foldFamily(node), version, module.mode);
}

std::vector<std::string> foldOptionNames(FoldNode node, std::size_t index)
{
    if (node != FoldNode::Opat)
        return {"E17", "E23"};
    if (index == 0)
        return {"E17", "E23", "E24", "E26", "E28"};
    return {"E17", "E23", "E26"};
}

namespace {

std::optional<int> FoldModuleOptions::*optionMember(std::string_view name)
{
    if (name == "E17")
        return &FoldModuleOptions::e17;
    if (name == "E23")
        return &FoldModuleOptions::e23;
    if (name == "E24")
        return &FoldModuleOptions::e24;
    if (name == "E26")
        return &FoldModuleOptions::e26;
    if (name == "E28")
        return &FoldModuleOptions::e28;
    return nullptr;
}

} // namespace

std::optional<int> foldOption(const FoldModuleOptions &options, std::string_view name)
{
    const auto member = optionMember(name);
    return member ? options.*member : std::nullopt;
}

void setFoldOption(FoldModuleOptions &options, std::string_view name, std::optional<int> value)
{
    if (const auto member = optionMember(name))
        options.*member = value;
}

FoldAddress foldAddress(FoldNode node, const FoldModule &module)
{
    return {node, module.address};
}

} // namespace vt::model
