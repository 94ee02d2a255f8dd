#include "new_file.h"

#include <algorithm>

namespace vt::model {

namespace {

constexpr int kOpatMaxModules = 8;
constexpr int kDmaMaxModules = 5;
const char *const kOpatMaster = "34";
const char *const kOpatSlave = "31";

bool isOpat(const dev::Dictionary &dict)
{
    return dict.family == "opat";
}

bool has(const std::vector<std::string> &list, const std::string &value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

} // namespace

bool NewFileChoice::valid() const
{
    if (!dictionary || dictionary->abstract)
        return false;
    if (modules < 1 || modules > maxModules(*dictionary))
        return false;
    if (!dictionary->versions.empty() && !has(dictionary->versions, version))
        return false;
    if (!dictionary->modes.empty() && !has(dictionary->modes, mode))
        return false;
    // A node with slaves is led by the OPAT master.
    return !(isOpat(*dictionary) && modules > 1 && version != kOpatMaster);
}

int maxModules(const dev::Dictionary &dictionary)
{
    if (dictionary.protocol != dev::DeviceProtocol::Hcs)
        return 1;
    return isOpat(dictionary) ? kOpatMaxModules : kDmaMaxModules;
}

std::vector<ModulePlace> modulePlaces(const NewFileChoice &choice)
{
    std::vector<ModulePlace> out;
    if (!choice.dictionary)
        return out;
    const dev::Dictionary &dict = *choice.dictionary;
    for (int i = 0; i < choice.modules; ++i) {
        ModulePlace place;
        place.version = choice.version;
        if (dict.protocol == dev::DeviceProtocol::Hart) {
            place.address = 0;
        } else if (dict.protocol == dev::DeviceProtocol::Dsp408) {
            place.address = 1;
        } else if (isOpat(dict)) {
            const bool master = i == 0 && choice.version == kOpatMaster;
            place.address = master ? 0 : (choice.version == kOpatMaster ? i : i + 1);
            place.version = master ? kOpatMaster : kOpatSlave;
        } else {
            place.address = i + 1;
        }
        out.push_back(std::move(place));
    }
    return out;
}

dev::files::ParamFile newParamFile(const NewFileChoice &choice, const std::string &tool,
                                   std::chrono::system_clock::time_point created)
{
    dev::files::ParamFile file;
    file.tool = tool;
    file.created = dev::files::isoUtc(created);
    if (!choice.valid())
        return file;
    const dev::Dictionary &dict = *choice.dictionary;
    for (const ModulePlace &place : modulePlaces(choice)) {
        dev::files::ModuleRecord module;
        module.address = place.address;
        module.family = dict.family;
        module.version = place.version;
        module.mode = choice.mode;
        for (const dev::ParamMeta &meta : dict.params) {
            if (!meta.writable() || !meta.defaultValue ||
                !meta.appliesTo(place.version, choice.mode))
                continue;
            module.values.push_back(dev::files::makeValueRow(meta, *meta.defaultValue));
        }
        file.modules.push_back(std::move(module));
    }
    return file;
}

} // namespace vt::model
