// HcsModuleObjects: see hcs_module_objects.h.
#include "sim/hcs_module_objects.h"

#include "sim/hcs_codes.h"

namespace vt::dev::sim {

void HcsModuleObjects::ModuleSink::setRaw(int id, std::int32_t value)
{
    exception =
        m_module.write(static_cast<std::uint16_t>(id), static_cast<std::uint16_t>(value)).exception;
}

HcsModuleObjects::HcsModuleObjects(HcsModule &module)
    : m_sink(module), m_objects(module.dictionary(), module.storage(), m_sink,
                                [&module](int id) { return module.storage().meta(id); })
{
}

Result<ObjectValue, SdoAbort> HcsModuleObjects::read(std::uint16_t index, std::uint8_t subindex)
{
    return m_objects.read(index, subindex);
}

std::optional<SdoAbort> HcsModuleObjects::write(std::uint16_t index, std::uint8_t subindex,
                                                std::uint32_t bits, std::size_t size)
{
    m_sink.exception = exce::kNone;
    if (auto abort = m_objects.write(index, subindex, bits, size))
        return abort;
    // HcsParamObjects has checked access and range already; what the module may still refuse:
    switch (m_sink.exception) {
    case exce::kNone: return std::nullopt;
    case exce::kWrongId: return SdoAbort{sdo_abort::kReadOnly};
    case exce::kWrongData: return SdoAbort{sdo_abort::kInvalidValue};
    // DMA Profinet manual §3.4.1: the EEPROM is still busy with the previous write (< 25 ms);
    // over Modbus this is EXCE 4 "writing of ID failed", in CiA 301 terms "cannot be stored".
    case exce::kWriteFailed: return SdoAbort{sdo_abort::kNotStored};
    default: return SdoAbort{sdo_abort::kGeneral};
    }
}

} // namespace vt::dev::sim
