#include "hcs_rows.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::access {

std::vector<HcsBlock> planHcsBlocks(std::span<const ParamMeta *const> rows,
                                    std::uint16_t maxPerBlock)
{
    std::vector<const ParamMeta *> sorted;
    for (const ParamMeta *row : rows) {
        if (row && row->id && row->readable() && *row->id >= 0 && *row->id <= 0xFFFF)
            sorted.push_back(row);
    }
    std::sort(sorted.begin(), sorted.end(),
              [](const ParamMeta *a, const ParamMeta *b) { return *a->id < *b->id; });
    sorted.erase(
        std::unique(sorted.begin(), sorted.end(),
                    [](const ParamMeta *a, const ParamMeta *b) { return *a->id == *b->id; }),
        sorted.end());

    std::vector<HcsBlock> blocks;
    const std::size_t limit = std::max<std::uint16_t>(maxPerBlock, 1);
    for (const ParamMeta *row : sorted) {
        const auto id = static_cast<std::uint16_t>(*row->id);
        if (!blocks.empty()) {
            HcsBlock &last = blocks.back();
            const auto next = static_cast<std::size_t>(last.firstId) + last.rows.size();
            if (next == id && last.rows.size() < limit) {
                last.rows.push_back(row);
                continue;
            }
        }
        blocks.push_back(HcsBlock{id, {row}});
    }
    return blocks;
}

std::vector<Transaction> planHcsReads(int module, std::span<const ParamMeta *const> rows,
                                      std::uint16_t maxPerBlock)
{
    std::vector<Transaction> plan;
    for (HcsBlock &block : planHcsBlocks(rows, maxPerBlock))
        plan.push_back(Transaction::read(module, std::move(block.rows)));
    return plan;
}

std::vector<Transaction> planHcsIdentify(int module)
{
    return {Transaction::identify(module, 0), Transaction::identify(module, 1)};
}

double registerToRaw(const ParamMeta &row, std::uint16_t word)
{
    switch (row.type) {
    case RawType::Int16:
    case RawType::Int32: return static_cast<double>(static_cast<std::int16_t>(word));
    case RawType::Int8:
        return static_cast<double>(
            static_cast<std::int8_t>(static_cast<std::uint8_t>(word & 0xFFu)));
    case RawType::UInt8: return static_cast<double>(word & 0xFFu);
    default: return static_cast<double>(word);
    }
}

std::optional<std::uint16_t> rawToRegister(const RawValue &value)
{
    if (isText(value))
        return std::nullopt;
    const double number = rawNumber(value);
    if (!std::isfinite(number) || std::trunc(number) != number || number < -32768.0 ||
        number > 65535.0)
        return std::nullopt;
    const auto integer = static_cast<std::int32_t>(number);
    return static_cast<std::uint16_t>(integer & 0xFFFF);
}

hcs::Family hcsFamilyOf(std::string_view dictionaryFamily)
{
    return dictionaryFamily.starts_with("opat") ? hcs::Family::Opat : hcs::Family::Dma;
}

} // namespace vt::dev::access
