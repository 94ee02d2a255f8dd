// HcsModuleObjects: the CANopen objects of one simulated HCS module for valvetune-sim's SDO
// server — HcsParamObjects (0x2000 + ID, sub 0; ARCHITECTURE.md "CAN") for the lookup, access and
// range checks, with every accepted download applied through HcsModule::write, so a CAN write
// obeys the module's rules as a Modbus write does (EEPROM time of the DMA Profinet manual §3.4.1,
// ID 0xB0 switches). Owner: SimDevice; single-threaded. The module must outlive it.
#pragma once

#include "sim/canopen_hcs_objects.h"
#include "sim/hcs_module.h"
#include "sim/object_dictionary.h"

#include <cstdint>

namespace vt::simapp {

class HcsModuleObjects : public dev::sim::ObjectDictionary
{
public:
    explicit HcsModuleObjects(dev::sim::HcsModule &module);

    dev::Result<dev::sim::ObjectValue, dev::sim::SdoAbort> read(std::uint16_t index,
                                                                std::uint8_t subindex) override;
    std::optional<dev::sim::SdoAbort> write(std::uint16_t index, std::uint8_t subindex,
                                            std::uint32_t bits, std::size_t size) override;

private:
    // HcsParamObjects' sink: hands the checked value to the module and keeps its EXCE.
    class ModuleSink : public dev::sim::ParamSink
    {
    public:
        explicit ModuleSink(dev::sim::HcsModule &module) : m_module(module) {}
        void setRaw(int id, std::int32_t value) override;
        std::uint8_t exception = 0;

    private:
        dev::sim::HcsModule &m_module;
    };

    ModuleSink m_sink;
    dev::sim::HcsParamObjects m_objects;
};

} // namespace vt::simapp
