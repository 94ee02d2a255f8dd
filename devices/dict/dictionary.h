// Dictionary: every parameter of one device family (docs/DICTIONARY.md), with lookups by name,
// HCS ID and Wandfluh IND/PNU/instance. DictionarySet: all families, loaded once at start-up and
// shared read-only afterwards (any thread may read).
#pragma once

#include "dict/device_protocol.h"
#include "dict/monitor_defaults.h"
#include "param_meta.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vt::dev {

struct Dictionary
{
    std::string family; // "dma-pn-v51"
    bool abstract = false;
    LocalText title;
    std::string vendor; // "HCS", "Wandfluh"
    DeviceProtocol protocol = DeviceProtocol::Hcs;
    std::string source;
    std::vector<std::string> versions;
    std::vector<std::string> modes;
    std::vector<ParamMeta> params; // in manual order
    // Least time between two single writes to one module (DMA Profinet manual §3.4.1: the EEPROM
    // needs up to 25 ms per parameter, "the cycle time of writing … should be greater than 30ms").
    int writePacingMs = 0;
    bool writePacingAssumed =
        false; // carried over from a sister manual, not stated for this family
    // The monitor's default channels and set-value rows (the "monitor" key).
    MonitorPlan monitor;

    const ParamMeta *find(const std::string &name) const;
    const ParamMeta *findId(int id) const;
    const ParamMeta *findIndPnu(int ind, int pnu, int instance = 0) const;
    // The DSP-408 device state machine (ED1/SD1 manual and HART-7 manual §4.2.2), which both
    // Wandfluh profiles command through db_ControlWord and report in db_StatusWord: the control
    // word row, or null for a family without that machine.
    const ParamMeta *stateControlWord() const;
    void buildIndex();

private:
    std::map<std::string, std::size_t> m_byName;
    std::map<int, std::size_t> m_byId;
    std::map<std::tuple<int, int, int>, std::size_t> m_byIndPnu;
};

struct DictionaryError
{
    std::string file; // "opat.json"
    std::string row;  // parameter name, or "#12" when the row has no name; empty for file-level
    std::string message;

    std::string text() const; // "opat.json, row C1.07: min 10 > max 5"
};

class DictionarySet
{
public:
    // Concrete (non-abstract) families, sorted by id.
    std::vector<std::string> families() const;
    const Dictionary *find(const std::string &family) const;
    void add(std::shared_ptr<const Dictionary> dictionary);

private:
    std::map<std::string, std::shared_ptr<const Dictionary>> m_families;
};

} // namespace vt::dev
