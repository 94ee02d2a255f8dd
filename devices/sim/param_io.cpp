#include "sim/param_io.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

double ParamRef::secondsPerRaw() const
{
    if (unit == "ms")
        return factor * 1e-3;
    return factor; // "s", and rows without unit that hold seconds
}

ParamRef findParam(const Dictionary &dict, std::initializer_list<std::string_view> names)
{
    for (std::string_view name : names) {
        const ParamMeta *meta = dict.find(std::string(name));
        if (!meta || !meta->id)
            continue;
        if (meta->access == Access::NotImplemented || meta->access == Access::Inactive)
            continue;
        ParamRef ref;
        ref.id = *meta->id;
        ref.factor = meta->scale.name.empty() ? 1.0 : meta->scale.factor;
        ref.min = meta->min;
        ref.max = meta->max;
        ref.unit = meta->unit;
        ref.meta = meta;
        return ref;
    }
    return {};
}

ParamRef findParam(const Dictionary &dict, std::string_view name)
{
    return findParam(dict, {name});
}

std::string branchName(std::string_view name, int branch)
{
    std::string out(name);
    if (out.size() >= 2 && (out[1] == '1' || out[1] == '2'))
        out[1] = static_cast<char>('0' + branch);
    return out;
}

std::int32_t ParamReader::raw(const ParamRef &ref, std::int32_t fallback) const
{
    return ref.valid() ? m_source.raw(ref.id) : fallback;
}

double ParamReader::value(const ParamRef &ref, double fallback) const
{
    return ref.valid() ? static_cast<double>(m_source.raw(ref.id)) * ref.factor : fallback;
}

double ParamReader::seconds(const ParamRef &ref, double fallback) const
{
    return ref.valid() ? static_cast<double>(m_source.raw(ref.id)) * ref.secondsPerRaw() : fallback;
}

std::int32_t ParamPublisher::toRaw(const ParamRef &ref, double value)
{
    const double raw = std::round(value / ref.factor);
    const double clamped = std::clamp(std::isfinite(raw) ? raw : 0.0, ref.min, ref.max);
    return static_cast<std::int32_t>(clamped);
}

void ParamPublisher::publish(const ParamRef &ref, double value)
{
    if (!ref.valid())
        return;
    const std::int32_t raw = toRaw(ref, value);
    const auto index = static_cast<std::size_t>(ref.id);
    if (index >= m_last.size())
        m_last.resize(index + 1);
    if (m_last[index] == raw)
        return;
    m_last[index] = raw;
    m_sink.setRaw(ref.id, raw);
}

ParamMemory::ParamMemory(const Dictionary &dict) : m_dict(&dict)
{
    for (const ParamMeta &p : dict.params)
        if (p.id && p.defaultValue)
            store(*p.id, static_cast<std::int32_t>(std::lround(*p.defaultValue)));
}

void ParamMemory::store(int id, std::int32_t value)
{
    if (id < 0)
        return;
    const auto index = static_cast<std::size_t>(id);
    if (index >= m_values.size())
        m_values.resize(index + 1, 0);
    m_values[index] = value;
}

std::int32_t ParamMemory::raw(int id) const
{
    const auto index = static_cast<std::size_t>(id);
    return id >= 0 && index < m_values.size() ? m_values[index] : 0;
}

void ParamMemory::setRaw(int id, std::int32_t value)
{
    store(id, value);
    ++m_writes;
}

bool ParamMemory::set(std::string_view name, std::int32_t value)
{
    const ParamMeta *meta = m_dict ? m_dict->find(std::string(name)) : nullptr;
    if (!meta || !meta->id)
        return false;
    store(*meta->id, value);
    return true;
}

std::int32_t ParamMemory::get(std::string_view name) const
{
    const ParamMeta *meta = m_dict ? m_dict->find(std::string(name)) : nullptr;
    return meta && meta->id ? raw(*meta->id) : 0;
}

} // namespace vt::dev::sim
