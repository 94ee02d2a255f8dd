// HcsStorage: the parameter image of one simulated HCS module — one raw value per parameter ID
// of the family's dictionary rows that apply to the module's version and mode, initialised to
// the dictionary defaults, plus the EEPROM copy that survives a power cycle. It is the plant's
// ParamSource (C/E/r/L/A rows) and ParamSink (d rows), so the plant and the bus see one image.
// Owner: HcsModule; single-threaded.
#pragma once

#include "dict/dictionary.h"
#include "sim/param_io.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev::sim {

class HcsStorage : public ParamSource, public ParamSink
{
public:
    // The dictionary must outlive the storage. version: the major version as the dictionary
    // writes it ("34", "31", "13"); mode: E00 as text ("3").
    HcsStorage(const Dictionary &dict, std::string version, std::string mode);

    // The row of `id` as this module has it: nullptr when the dictionary has no such ID or the
    // row belongs to another version or mode (OPAT master-only / slave-only rows).
    const ParamMeta *meta(int id) const;
    const ParamMeta *find(std::string_view name) const; // same, by name
    const Dictionary &dictionary() const { return m_dict; }

    // ParamSource / ParamSink: raw values as the plant sees them (int16 rows signed, uint16 rows
    // 0..65535). IDs the module does not have read 0 and ignore writes.
    std::int32_t raw(int id) const override;
    void setRaw(int id, std::int32_t value) override;
    std::int32_t get(std::string_view name) const;
    bool set(std::string_view name, std::int32_t raw);

    // What a wire read returns and a wire write carries: the 16-bit word.
    std::uint16_t word(int id) const { return static_cast<std::uint16_t>(raw(id)); }
    // The wire word as the row's type reads it: int8/int16 sign-extended, unsigned as is.
    static std::int32_t fromWord(const ParamMeta &meta, std::uint16_t word);

    // EEPROM copy: what the module holds after a power cycle.
    void commit(int id, std::int32_t value);
    std::int32_t committed(int id) const;
    // Power cycle: EEPROM rows come back from the EEPROM copy, every other row from its default.
    void restoreAfterPowerCycle();

    // The value a row starts with: its default, or (no default in the manual) 0 pulled into
    // [min, max]. Tests use the same rule to know what to expect.
    static std::int32_t defaultRaw(const ParamMeta &meta);
    static bool isEeprom(const ParamMeta &meta) { return meta.persistence == Persistence::Eeprom; }

private:
    std::size_t index(int id) const { return static_cast<std::size_t>(id); }
    bool has(int id) const { return id >= 0 && index(id) < m_rows.size() && m_rows[index(id)]; }

    const Dictionary &m_dict;
    std::vector<const ParamMeta *> m_rows; // by ID: the applicable row or nullptr
    std::vector<std::int32_t> m_values;    // by ID
    std::vector<std::int32_t> m_eeprom;    // by ID: committed values of EEPROM rows
};

} // namespace vt::dev::sim
