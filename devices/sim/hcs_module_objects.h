// HcsModuleObjects: the CANopen objects of one simulated HCS module for the SDO server —
// HcsParamObjects (0x2000 + ID, sub 0; ARCHITECTURE.md "CAN") for the lookup, access and range
// checks, with every accepted download applied through HcsModule::write, so a CAN write obeys the
// module's rules as a Modbus write does (EEPROM time of the DMA Profinet manual §3.4.1, ID 0xB0
// switches). Owner: SimDevice; single-threaded. The module must outlive it.
#pragma once

#include "sim/canopen_hcs_objects.h"
#include "sim/hcs_module.h"
#include "sim/object_dictionary.h"

#include <cstdint>

namespace vt::dev::sim {

class HcsModuleObjects : public ObjectDictionary
{
public:
    explicit HcsModuleObjects(HcsModule &module);

    Result<ObjectValue, SdoAbort> read(std::uint16_t index, std::uint8_t subindex) override;
    std::optional<SdoAbort> write(std::uint16_t index, std::uint8_t subindex, std::uint32_t bits,
                                  std::size_t size) override;

private:
    // HcsParamObjects' sink: hands the checked value to the module and keeps its EXCE.
    class ModuleSink : public ParamSink
    {
    public:
        explicit ModuleSink(HcsModule &module) : m_module(module) {}
        void setRaw(int id, std::int32_t value) override;
        std::uint8_t exception = 0;

    private:
        HcsModule &m_module;
    };

    ModuleSink m_sink;
    HcsParamObjects m_objects;
};

} // namespace vt::dev::sim
