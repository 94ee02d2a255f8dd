#include "sim_memory.h"

#include "model/session/sim_endpoint.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vt::cli {

namespace {

// Per module: (ID, raw) of every writable row.
using NodeImage = std::vector<std::vector<std::pair<int, std::int32_t>>>;

std::map<std::string, NodeImage> &memory()
{
    static std::map<std::string, NodeImage> images;
    return images;
}

std::string keyOf(const model::SimSpec &spec)
{
    const std::string protocol = spec.protocol ? dev::key(*spec.protocol) : "";
    return spec.family + ':' + std::to_string(spec.modules) + ':' + protocol + ':' +
           std::to_string(spec.mode) + (spec.factory ? ":factory" : "");
}

} // namespace

void restoreSimulator(model::SimEndpoint &sim)
{
    dev::sim::HcsNode *node = sim.node();
    const auto it = memory().find(keyOf(sim.spec()));
    if (!node || it == memory().end())
        return; // HART simulator: not kept (open point); first connection: fresh
    for (std::size_t i = 0; i < node->moduleCount() && i < it->second.size(); ++i) {
        dev::sim::HcsStorage &storage = node->module(i).storage();
        for (const auto &[id, raw] : it->second[i]) {
            storage.setRaw(id, raw);
            storage.commit(id, raw);
        }
    }
}

void rememberSimulator(const model::SimEndpoint &sim)
{
    const dev::sim::HcsNode *node = sim.node();
    if (!node)
        return;
    NodeImage image(node->moduleCount());
    for (std::size_t i = 0; i < node->moduleCount(); ++i) {
        const dev::sim::HcsStorage &storage = node->module(i).storage();
        for (const dev::ParamMeta &row : storage.dictionary().params) {
            if (row.id && row.writable() && storage.meta(*row.id) == &row)
                image[i].emplace_back(*row.id, storage.raw(*row.id));
        }
    }
    memory()[keyOf(sim.spec())] = std::move(image);
}

void forgetSimulators()
{
    memory().clear();
}

} // namespace vt::cli
