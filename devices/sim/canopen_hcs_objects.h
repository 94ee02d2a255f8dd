// The manufacturer objects of an HCS parameter image for the CANopen SDO server: parameter ID n
// is object 0x2000 + n, sub-index 0, unless the row names its own `canopen` object
// (ARCHITECTURE.md "CAN", docs/DICTIONARY.md). Values are the 16-bit words of the HCS telegrams
// (int8/int16 rows sign-extended). Any image that is a ParamSource/ParamSink plugs in (the
// HcsStorage is both); `lookup` says which rows the module has (version and mode).
// Owner: whoever builds the simulator; single-threaded. Dictionary and image must outlive it.
#pragma once

#include "dict/dictionary.h"
#include "sim/object_dictionary.h"
#include "sim/param_io.h"

#include <functional>

namespace vt::dev::sim {

class HcsParamObjects : public ObjectDictionary
{
public:
    static constexpr std::uint16_t kBase = 0x2000;
    using Lookup = std::function<const ParamMeta *(int id)>;

    // Without `lookup` every row of the dictionary with an ID exists.
    HcsParamObjects(const Dictionary &dict, ParamSource &source, ParamSink &sink,
                    Lookup lookup = {});

    Result<ObjectValue, SdoAbort> read(std::uint16_t index, std::uint8_t subindex) override;
    std::optional<SdoAbort> write(std::uint16_t index, std::uint8_t subindex, std::uint32_t bits,
                                  std::size_t size) override;

private:
    Result<const ParamMeta *, SdoAbort> find(std::uint16_t index, std::uint8_t subindex) const;

    const Dictionary &m_dict;
    ParamSource &m_source;
    ParamSink &m_sink;
    Lookup m_lookup;
};

} // namespace vt::dev::sim
