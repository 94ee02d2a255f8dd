#include "sim_memory.h"

#include "model/session/sim_endpoint.h"
#include "sim/dsp408_device.h"
#include "sim/hart_device.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vt::cli {

namespace {

// What one simulator held: HCS per module (ID, raw) of every writable row; a Wandfluh device
// (ED1/SD1, SD7) (name, raw) of every writable IND/PNU row, and the SD7's universal texts.
struct Image
{
    std::vector<std::vector<std::pair<int, std::int32_t>>> modules;
    std::vector<std::pair<std::string, double>> wandfluh;
    std::optional<dev::sim::HartDevice::Texts> texts;
};

std::map<std::string, Image> &memory()
{
    static std::map<std::string, Image> images;
    return images;
}

dev::sim::Dsp408ParamStore *wandfluhStore(const model::SimEndpoint &sim)
{
    if (dev::sim::HartDevice *hart = sim.hart())
        return &hart->params();
    if (dev::sim::Dsp408Device *ed1 = sim.ed1())
        return &ed1->params();
    return nullptr;
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
    const auto it = memory().find(keyOf(sim.spec()));
    if (it == memory().end())
        return; // first connection: fresh
    const Image &image = it->second;
    if (dev::sim::HcsNode *node = sim.node()) {
        for (std::size_t i = 0; i < node->moduleCount() && i < image.modules.size(); ++i) {
            dev::sim::HcsStorage &storage = node->module(i).storage();
            for (const auto &[id, raw] : image.modules[i]) {
                storage.setRaw(id, raw);
                storage.commit(id, raw);
            }
        }
    }
    if (dev::sim::Dsp408ParamStore *store = wandfluhStore(sim))
        for (const auto &[name, raw] : image.wandfluh)
            store->set(name, raw);
    if (dev::sim::HartDevice *hart = sim.hart(); hart && image.texts)
        hart->setTexts(*image.texts);
}

void rememberSimulator(const model::SimEndpoint &sim)
{
    Image image;
    if (const dev::sim::HcsNode *node = sim.node()) {
        image.modules.resize(node->moduleCount());
        for (std::size_t i = 0; i < node->moduleCount(); ++i) {
            const dev::sim::HcsStorage &storage = node->module(i).storage();
            for (const dev::ParamMeta &row : storage.dictionary().params) {
                if (row.id && row.writable() && storage.meta(*row.id) == &row)
                    image.modules[i].emplace_back(*row.id, storage.raw(*row.id));
            }
        }
    }
    if (const dev::sim::Dsp408ParamStore *store = wandfluhStore(sim)) {
        for (const dev::ParamMeta &row : store->dictionary().params)
            if (row.writable() && store->find(row.name) == &row)
                image.wandfluh.emplace_back(row.name, store->value(row));
    }
    if (const dev::sim::HartDevice *hart = sim.hart())
        image.texts = hart->texts();
    memory()[keyOf(sim.spec())] = std::move(image);
}

void forgetSimulators()
{
    memory().clear();
}

} // namespace vt::cli
