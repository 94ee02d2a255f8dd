#include "sim/hcs_storage.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

HcsStorage::HcsStorage(const Dictionary &dict, std::string version, std::string mode) : m_dict(dict)
{
    int maxId = -1;
    for (const ParamMeta &p : dict.params)
        if (p.id)
            maxId = std::max(maxId, *p.id);
    const auto size = static_cast<std::size_t>(maxId + 1);
    m_rows.assign(size, nullptr);
    m_values.assign(size, 0);
    m_eeprom.assign(size, 0);
    for (const ParamMeta &p : dict.params) {
        if (!p.id || *p.id < 0 || !p.appliesTo(version, mode))
            continue;
        m_rows[index(*p.id)] = &p;
        m_values[index(*p.id)] = defaultRaw(p);
        m_eeprom[index(*p.id)] = defaultRaw(p);
    }
}

const ParamMeta *HcsStorage::meta(int id) const
{
    return has(id) ? m_rows[index(id)] : nullptr;
}

const ParamMeta *HcsStorage::find(std::string_view name) const
{
    const ParamMeta *row = m_dict.find(std::string(name));
    return row && row->id && meta(*row->id) == row ? row : nullptr;
}

std::int32_t HcsStorage::raw(int id) const
{
    return has(id) ? m_values[index(id)] : 0;
}

void HcsStorage::setRaw(int id, std::int32_t value)
{
    if (has(id))
        m_values[index(id)] = value;
}

std::int32_t HcsStorage::get(std::string_view name) const
{
    const ParamMeta *row = find(name);
    return row ? raw(*row->id) : 0;
}

bool HcsStorage::set(std::string_view name, std::int32_t value)
{
    const ParamMeta *row = find(name);
    if (!row)
        return false;
    setRaw(*row->id, value);
    return true;
}

std::int32_t HcsStorage::fromWord(const ParamMeta &meta, std::uint16_t word)
{
    switch (meta.type) {
    case RawType::Int8: return static_cast<std::int8_t>(word & 0xFFu);
    case RawType::UInt8: return word & 0xFF;
    case RawType::UInt16:
    case RawType::UInt32: return word;
    default: return static_cast<std::int16_t>(word);
    }
}

void HcsStorage::commit(int id, std::int32_t value)
{
    if (has(id))
        m_eeprom[index(id)] = value;
}

std::int32_t HcsStorage::committed(int id) const
{
    return has(id) ? m_eeprom[index(id)] : 0;
}

void HcsStorage::restoreAfterPowerCycle()
{
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i])
            m_values[i] = isEeprom(*m_rows[i]) ? m_eeprom[i] : defaultRaw(*m_rows[i]);
}

std::int32_t HcsStorage::defaultRaw(const ParamMeta &meta)
{
    if (meta.defaultValue)
        return static_cast<std::int32_t>(std::lround(*meta.defaultValue));
    if (meta.min > meta.max)
        return 0;
    return static_cast<std::int32_t>(std::clamp(0.0, meta.min, meta.max));
}

} // namespace vt::dev::sim
