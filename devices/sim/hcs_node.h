// HcsNode: a simulated fieldbus node with its HCS modules, answering the gateway telegrams a PLC
// sends (CMD 3 / 6 / 15) byte for byte, with the node's rules:
//  * it answers only when the request bytes differ from the previous request (TADR toggling;
//    OPAT manual §1.5, DMA Profinet manual §1.4);
//  * CMD 15 hands every module its share and answers for one module per telegram, module by
//    module in address order (OPAT manual §3.2: master first, then slaves 1, 2, …; DMA Profinet
//    manual §4.2 / §4.4.2: E22 = 1, 2, 3, then 1 again);
//  * its exceptions: missing module (CMD 3/6: 5, CMD 15: 8 with the missing SADR), duplicate
//    addresses (OPAT 12; DMA 6, assumed), SNUM not matching the node (7), telegram longer than
//    the output buffer / cut short (9, SADR 0), unknown command (1).
// OPAT: master SADR 0 + CAN slaves 1..7 (OPAT manual §1.4). DMA: modules addressed by E22, 1..32
// for CMD 3/6, CMD 15 only 1..5 (DMA Profinet manual §1.5).
// Owner: whoever built it (node_config.h's makeNode); single-threaded, with the SimClock.
#pragma once

#include "hcs/types.h"
#include "sim/hcs_answer_queue.h"
#include "sim/hcs_module.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::sim {

struct HcsNodeOptions
{
    // The PLC's output image in bytes (the GSD module, DMA Profinet manual §4.5.4 "IN/OUT 42
    // byte"; DMA Profibus Anleitung §5.1 "CMD15 5fold 9B-I 28B-O"). A CMD 15 telegram longer than
    // this gets exception 9. 0: no limit (telegrams as they come).
    std::size_t outputBufferBytes = 0;
    // OPAT manual §1.5 / DMA Profinet manual §1.4: "only responding if a received message …
    // contains changed (different) data compared to the previous message".
    bool answerOnlyOnChange = true;
};

class HcsNode
{
public:
    HcsNode(SimClock &clock, hcs::Family family, HcsNodeOptions options = {});

    hcs::Family family() const { return m_family; }
    const HcsNodeOptions &options() const { return m_options; }
    void setOptions(const HcsNodeOptions &options) { m_options = options; }
    SimClock &clock() { return m_clock; }

    // The node owns its modules; references stay valid for the node's lifetime.
    HcsModule &addModule(HcsModuleConfig config);
    std::size_t moduleCount() const { return m_modules.size(); }
    HcsModule &module(std::size_t index) { return *m_modules[index]; }
    const HcsModule &module(std::size_t index) const { return *m_modules[index]; }
    // Powered modules that answer to `address` now (OPAT: 0 / DIP switch; DMA: E22). Two or more
    // is the duplicate-address fault: set it with HcsModule::setAddress.
    std::vector<HcsModule *> modulesAt(std::uint8_t address) const;

    // One telegram (or a PLC image that starts with one; the rest is padding) in, the node's
    // answer out — nullopt when the node stays silent (unchanged request, CMD 0 = idle image,
    // fewer than 3 bytes). A write delayed by a busy EEPROM is ready later than now.
    std::optional<TimedBytes> process(std::span<const std::uint8_t> request);

    // Forget the previous request, so the next one is answered even if it is the same (the
    // PLC reconnected).
    void resetChangeDetection() { m_lastRequest.reset(); }
    // Address of the module that answers the next CMD 15 (for tests and the inspector).
    std::optional<std::uint8_t> nextCyclicAddress(std::size_t modules) const;

private:
    Bytes exception(std::uint8_t tadr, std::uint8_t sadr, std::uint8_t command,
                    std::uint8_t code) const;
    std::uint8_t addressFault(std::size_t found) const; // 0 ok, else the EXCE for `found` modules
    TimedBytes read(std::span<const std::uint8_t> request);
    TimedBytes write(std::span<const std::uint8_t> request);
    TimedBytes cyclic(std::span<const std::uint8_t> request);
    std::size_t cyclicCapable() const; // powered modules CMD 15 can reach

    SimClock &m_clock;
    hcs::Family m_family;
    HcsNodeOptions m_options;
    std::vector<std::unique_ptr<HcsModule>> m_modules;
    std::optional<Bytes> m_lastRequest;
    std::size_t m_nextResponder = 0; // index into the CMD 15 module list
};

} // namespace vt::dev::sim
