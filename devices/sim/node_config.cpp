#include "sim/node_config.h"

#include "dict/dictionary_loader.h"

#include <algorithm>

namespace vt::dev::sim {
namespace {

// OPAT manual §1.2: V34 = Profibus master (SADR 0), V31 = CAN slave.
constexpr const char *kOpatMasterVersion = "34";
constexpr const char *kOpatSlaveVersion = "31";
// OPAT manual §1.4: up to 7 CAN slaves; DMA Profinet manual §1.5: "Theoretically up to 32 slaves".
constexpr std::size_t kOpatMaxModules = 8;
constexpr std::size_t kDmaMaxModules = 32;

bool has(const std::vector<std::string> &list, const std::string &value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

} // namespace

std::vector<std::string> simulatedFamilies(const DictionarySet &set)
{
    std::vector<std::string> out;
    for (const std::string &family : set.families()) {
        const Dictionary *dict = set.find(family);
        if (dict && dict->protocol == DeviceProtocol::Hcs && !dict->abstract)
            out.push_back(family);
    }
    return out;
}

Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, const DictionarySet &set,
                                                       const NodeConfig &config)
{
    const Dictionary *dict = set.find(config.family);
    if (!dict || dict->abstract || dict->protocol != DeviceProtocol::Hcs)
        return std::string("no HCS dictionary family '" + config.family + "'");
    const hcs::Family family = hcsFamilyOf(*dict);
    const std::size_t max = family == hcs::Family::Opat ? kOpatMaxModules : kDmaMaxModules;
    if (config.modules < 1 || config.modules > max)
        return std::string(config.family + ": " + std::to_string(config.modules) +
                           " modules; a node has 1.." + std::to_string(max));
    if (config.mode != 0 && !has(dict->modes, std::to_string(config.mode)))
        return std::string(config.family + " has no mode " + std::to_string(config.mode));
    if (!config.addresses.empty() && config.addresses.size() != config.modules)
        return std::string(config.family + ": " + std::to_string(config.addresses.size()) +
                           " addresses for " + std::to_string(config.modules) + " modules");
    std::string dmaVersion =
        config.version.empty() && !dict->versions.empty() ? dict->versions.back() : config.version;
    if (family == hcs::Family::Dma && !has(dict->versions, dmaVersion))
        return std::string(config.family + " has no version " + dmaVersion);

    auto node = std::make_unique<HcsNode>(clock, family, config.node);
    for (std::size_t i = 0; i < config.modules; ++i) {
        HcsModuleConfig m = config.moduleTemplate;
        m.dictionary = dict;
        m.mode = config.mode;
        if (family == hcs::Family::Opat) {
            m.version = i == 0 ? kOpatMasterVersion : kOpatSlaveVersion;
            m.address = static_cast<std::uint8_t>(i); // master 0, DIP switches 1..7
        } else {
            m.version = dmaVersion;
            m.address =
                static_cast<std::uint8_t>(i + 1); // E22 = 1, 2, … (DMA Profinet manual §4.1)
        }
        if (!config.addresses.empty())
            m.address = config.addresses[i];
        node->addModule(std::move(m));
    }
    return node;
}

Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, const NodeConfig &config)
{
    const auto &set = builtinDictionaries();
    if (!set)
        return std::string("the built-in dictionaries do not load");
    return makeNode(clock, *set, config);
}

Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, std::string_view family,
                                                       std::size_t modules)
{
    NodeConfig config;
    config.family = std::string(family);
    config.modules = modules;
    return makeNode(clock, config);
}

} // namespace vt::dev::sim
