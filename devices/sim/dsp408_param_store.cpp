#include "sim/dsp408_param_store.h"

#include "hart/data_types.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {
namespace {

bool implemented(const ParamMeta &meta)
{
    return meta.access != Access::NotImplemented && meta.access != Access::Inactive &&
           !meta.isString();
}

} // namespace

Dsp408ParamStore::Dsp408ParamStore(const Dictionary &dictionary)
    : m_dict(&dictionary), m_values(dictionary.params.size(), 0.0)
{
    resetDefaults();
}

const ParamMeta *Dsp408ParamStore::find(int ind, int pnu, int instance) const
{
    const ParamMeta *meta = m_dict->findIndPnu(ind, pnu, instance);
    return meta && implemented(*meta) ? meta : nullptr;
}

const ParamMeta *Dsp408ParamStore::find(std::string_view name) const
{
    const ParamMeta *meta = m_dict->find(std::string(name));
    return meta && implemented(*meta) ? meta : nullptr;
}

std::size_t Dsp408ParamStore::indexOf(const ParamMeta &meta) const
{
    return static_cast<std::size_t>(&meta - m_dict->params.data());
}

double Dsp408ParamStore::value(const ParamMeta &meta) const
{
    const std::size_t i = indexOf(meta);
    return i < m_values.size() ? m_values[i] : 0.0;
}

double Dsp408ParamStore::value(std::string_view name, double fallback) const
{
    const ParamMeta *meta = find(name);
    return meta ? value(*meta) : fallback;
}

void Dsp408ParamStore::set(const ParamMeta &meta, double raw)
{
    const std::size_t i = indexOf(meta);
    if (i < m_values.size())
        m_values[i] = raw;
}

bool Dsp408ParamStore::set(std::string_view name, double raw)
{
    const ParamMeta *meta = find(name);
    if (!meta)
        return false;
    set(*meta, raw);
    return true;
}

Limits Dsp408ParamStore::limits(const ParamMeta &meta) const
{
    Limits l = rowLimits(meta);
    if (!meta.minParam.empty())
        if (const ParamMeta *other = find(meta.minParam))
            l.min = std::max(l.min, value(*other));
    if (!meta.maxParam.empty())
        if (const ParamMeta *other = find(meta.maxParam))
            l.max = std::min(l.max, value(*other));
    return l;
}

std::optional<ParamErrc> Dsp408ParamStore::checkWrite(const ParamMeta &meta, double raw) const
{
    if (!meta.writable())
        return ParamErrc::ReadOnly;
    if (!meta.isFloat() && raw != std::floor(raw))
        return ParamErrc::InvalidValue;
    const Limits l = limits(meta);
    if (!std::isfinite(raw) || raw < l.min)
        return ParamErrc::BelowMin;
    if (raw > l.max)
        return ParamErrc::AboveMax;
    return std::nullopt;
}

double Dsp408ParamStore::defaultOf(const ParamMeta &meta)
{
    if (meta.defaultValue)
        return *meta.defaultValue;
    // No default in the manual and none assumed: 0, or the nearest limit when 0 is out of range.
    return std::clamp(0.0, std::min(meta.min, meta.max), std::max(meta.min, meta.max));
}

void Dsp408ParamStore::resetDefaults()
{
    for (std::size_t i = 0; i < m_values.size(); ++i)
        m_values[i] = defaultOf(m_dict->params[i]);
}

bool isModeRow(const ParamMeta &meta)
{
    return meta.name == "db_DeviceMode" || meta.name == "db_ControlMode" || meta.name == "db_Local";
}

std::uint32_t toWireBits(const ParamMeta &meta, double raw)
{
    if (meta.isFloat())
        return hart::bitsFromFloat(static_cast<float>(raw));
    const auto clamped = std::clamp(raw, typeMin(meta.type), typeMax(meta.type));
    const auto wide = static_cast<std::int64_t>(clamped);
    const std::size_t width = wireBytes(meta.type);
    const std::uint64_t mask = width >= 4 ? 0xFFFFFFFFu : (std::uint64_t{1} << (8 * width)) - 1;
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(wide) & mask);
}

double fromWireBits(const ParamMeta &meta, std::uint32_t bits)
{
    switch (meta.type) {
    case RawType::Int8: return static_cast<std::int8_t>(static_cast<std::uint8_t>(bits));
    case RawType::UInt8: return static_cast<std::uint8_t>(bits);
    case RawType::Int16: return static_cast<std::int16_t>(static_cast<std::uint16_t>(bits));
    case RawType::UInt16: return static_cast<std::uint16_t>(bits);
    case RawType::Int32: return static_cast<std::int32_t>(bits);
    case RawType::UInt32: return bits;
    case RawType::Float32: return hart::floatFromBits(bits);
    case RawType::String: return 0;
    }
    return 0;
}

} // namespace vt::dev::sim
