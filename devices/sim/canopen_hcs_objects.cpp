#include "sim/canopen_hcs_objects.h"

#include "dict/cooking.h"

#include <utility>

namespace vt::dev::sim {
namespace {

bool exists(const ParamMeta *meta)
{
    return meta && meta->id && meta->access != Access::NotImplemented &&
           meta->access != Access::Inactive;
}

std::uint16_t objectIndex(const ParamMeta &meta)
{
    return meta.canopen ? meta.canopen->index
                        : static_cast<std::uint16_t>(HcsParamObjects::kBase + *meta.id);
}

std::uint8_t objectSub(const ParamMeta &meta)
{
    return meta.canopen ? meta.canopen->sub : 0;
}

} // namespace

HcsParamObjects::HcsParamObjects(const Dictionary &dict, ParamSource &source, ParamSink &sink,
                                 Lookup lookup)
    : m_dict(dict), m_source(source), m_sink(sink), m_lookup(std::move(lookup))
{
    if (!m_lookup)
        m_lookup = [this](int id) { return m_dict.findId(id); };
}

Result<const ParamMeta *, SdoAbort> HcsParamObjects::find(std::uint16_t index,
                                                          std::uint8_t subindex) const
{
    bool indexSeen = false;
    for (const ParamMeta &row : m_dict.params) {
        if (!row.id)
            continue;
        const ParamMeta *meta = m_lookup(*row.id);
        if (!exists(meta) || meta != &row || objectIndex(row) != index)
            continue;
        indexSeen = true;
        if (objectSub(row) == subindex)
            return meta;
    }
    return SdoAbort{indexSeen ? sdo_abort::kNoSubindex : sdo_abort::kNoObject};
}

Result<ObjectValue, SdoAbort> HcsParamObjects::read(std::uint16_t index, std::uint8_t subindex)
{
    auto meta = find(index, subindex);
    if (!meta.ok())
        return meta.error();
    if (!(*meta)->readable())
        return SdoAbort{sdo_abort::kWriteOnly};
    const auto word = static_cast<std::uint16_t>(m_source.raw(*(*meta)->id));
    return ObjectValue{word, 2};
}

std::optional<SdoAbort> HcsParamObjects::write(std::uint16_t index, std::uint8_t subindex,
                                               std::uint32_t bits, std::size_t size)
{
    auto found = find(index, subindex);
    if (!found.ok())
        return found.error();
    const ParamMeta &meta = **found;
    if (!meta.writable())
        return SdoAbort{sdo_abort::kReadOnly};
    if (auto abort = lengthAbort(size, 2)) // HCS parameters are 16-bit words
        return abort;
    const auto word = static_cast<std::uint16_t>(bits);
    const bool isSigned = meta.type == RawType::Int8 || meta.type == RawType::Int16;
    const std::int32_t raw = isSigned ? static_cast<std::int16_t>(word) : word;
    if (auto error = checkRange(meta, raw)) {
        if (error->kind == CookError::Kind::AboveMax)
            return SdoAbort{sdo_abort::kValueTooHigh};
        return SdoAbort{sdo_abort::kValueTooLow};
    }
    m_sink.setRaw(*meta.id, raw);
    return std::nullopt;
}

} // namespace vt::dev::sim
