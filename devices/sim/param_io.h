// Parameter access of the plant: it reads C/E/r/L/A values through ParamSource and writes the
// d-values through ParamSink, so the module (or a test) keeps the storage. IDs are looked up by
// name in the family's Dictionary once (ParamRef), because the families number rows differently.
#pragma once

#include "dict/dictionary.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev::sim {

class ParamSource
{
public:
    virtual ~ParamSource() = default;
    virtual std::int32_t raw(int id) const = 0;
};

class ParamSink
{
public:
    virtual ~ParamSink() = default;
    virtual void setRaw(int id, std::int32_t value) = 0;
};

// One resolved row: its ID, scale and raw limits. An invalid ref (row not in the family) reads
// as the caller's fallback and is never written.
struct ParamRef
{
    int id = -1;
    double factor = 1.0;     // display = raw × factor (the row's scale)
    double min = 0, max = 0; // raw limits
    std::string unit;
    const ParamMeta *meta = nullptr; // owned by the Dictionary, which outlives the plant

    bool valid() const { return id >= 0; }
    // The row's time value in seconds ("ms" rows: 1 == 10 ms; "s" rows: 100 == 1.00 s).
    double secondsPerRaw() const;
};

// The first of `names` the family has (OPAT "E03" is DMA "E1.03"); an invalid ref when none.
// Rows with access `n` or `x` do not exist for the plant.
ParamRef findParam(const Dictionary &dict, std::initializer_list<std::string_view> names);
ParamRef findParam(const Dictionary &dict, std::string_view name);
// "C1.13" for branch 2 becomes "C2.13": branch rows carry the branch as the digit after the block.
std::string branchName(std::string_view name, int branch);

// Reads cooked values: raw × factor, or the fallback for rows the family does not have.
class ParamReader
{
public:
    explicit ParamReader(const ParamSource &source) : m_source(source) {}
    std::int32_t raw(const ParamRef &ref, std::int32_t fallback) const;
    double value(const ParamRef &ref, double fallback) const;
    double seconds(const ParamRef &ref, double fallback) const;

private:
    const ParamSource &m_source;
};

// Writes display values: rounds to the row's raw step, clamps to its range and only calls the
// sink when the raw value changed (the plant runs 2000 steps/s; the module need not see them all).
class ParamPublisher
{
public:
    explicit ParamPublisher(ParamSink &sink) : m_sink(sink) {}
    void publish(const ParamRef &ref, double value);
    static std::int32_t toRaw(const ParamRef &ref, double value);

private:
    ParamSink &m_sink;
    std::vector<std::optional<std::int32_t>> m_last; // by ID
};

// A plain value store for tests and tools: raw values per ID, filled with the dictionary's
// defaults. Not thread-safe.
class ParamMemory : public ParamSource, public ParamSink
{
public:
    ParamMemory() = default;
    explicit ParamMemory(const Dictionary &dict);

    std::int32_t raw(int id) const override;
    void setRaw(int id, std::int32_t value) override;
    // Sets a row by name; returns false when the family has no such row.
    bool set(std::string_view name, std::int32_t raw);
    std::int32_t get(std::string_view name) const;
    std::size_t writes() const { return m_writes; }

private:
    void store(int id, std::int32_t value);

    const Dictionary *m_dict = nullptr;
    std::vector<std::int32_t> m_values; // by ID; HCS IDs are dense (0 … ~260)
    std::size_t m_writes = 0;
};

} // namespace vt::dev::sim
