#include "sim/hcs_node.h"

#include "hcs/telegram.h"
#include "sim/hcs_codes.h"

namespace vt::dev::sim {

HcsNode::HcsNode(SimClock &clock, hcs::Family family, HcsNodeOptions options)
    : m_clock(clock), m_family(family), m_options(options)
{
}

HcsModule &HcsNode::addModule(HcsModuleConfig config)
{
    m_modules.push_back(std::make_unique<HcsModule>(m_clock, std::move(config)));
    return *m_modules.back();
}

std::vector<HcsModule *> HcsNode::modulesAt(std::uint8_t address) const
{
    std::vector<HcsModule *> found;
    for (const auto &m : m_modules)
        if (m->powered() && m->address() == address)
            found.push_back(m.get());
    return found;
}

std::optional<std::uint8_t> HcsNode::nextCyclicAddress(std::size_t modules) const
{
    if (modules == 0)
        return std::nullopt;
    return hcs::moduleAddress(m_family, m_nextResponder % modules);
}

Bytes HcsNode::exception(std::uint8_t tadr, std::uint8_t sadr, std::uint8_t command,
                         std::uint8_t code) const
{
    return hcs::encode(hcs::ExceptionResponse{tadr, sadr, command, code});
}

std::uint8_t HcsNode::addressFault(std::size_t found) const
{
    if (found <= 1)
        return exce::kNone;
    // OPAT manual §2.3 / §2.6 / §3.3 code 12; the DMA tables have none: two modules answering
    // on the node's internal Modbus line garble each other (code 6, an assumption).
    return m_family == hcs::Family::Opat ? exce::kDuplicateAddress : exce::kChecksum;
}

std::size_t HcsNode::cyclicCapable() const
{
    const unsigned lo = m_family == hcs::Family::Opat ? 0 : 1;
    const unsigned hi = m_family == hcs::Family::Opat ? 7 : 5;
    std::size_t n = 0;
    for (const auto &m : m_modules)
        if (m->powered() && m->address() >= lo && m->address() <= hi)
            ++n;
    return n;
}

std::optional<TimedBytes> HcsNode::process(std::span<const std::uint8_t> request)
{
    if (request.size() < hcs::kCyclicHeaderSize)
        return std::nullopt;
    Bytes copy(request.begin(), request.end());
    if (m_options.answerOnlyOnChange && m_lastRequest == copy)
        return std::nullopt;
    m_lastRequest = std::move(copy);
    const std::uint8_t command = request[2];
    switch (command) {
    case 0: return std::nullopt; // an all-zero PLC image: nothing requested yet
    case hcs::kCmdRead: return read(request);
    case hcs::kCmdWrite: return write(request);
    case hcs::kCmdCyclic: return cyclic(request);
    default:
        return TimedBytes{
            exception(request[0], request[1], command & 0x7F, exce::kCommandNotSupported),
            m_clock.nowUs()};
    }
}

TimedBytes HcsNode::read(std::span<const std::uint8_t> request)
{
    const std::int64_t now = m_clock.nowUs();
    const auto q = hcs::decodeReadRequest(request, {m_family, true});
    if (!q) // only Truncated is possible here: the telegram was cut short
        return {exception(request[0], request[1], hcs::kCmdRead, exce::kBufferTooSmall), now};
    const auto modules = modulesAt(q->sadr);
    if (modules.empty())
        return {exception(q->tadr, q->sadr, hcs::kCmdRead, exce::kSlaveTimeout), now};
    if (const std::uint8_t fault = addressFault(modules.size()))
        return {exception(q->tadr, q->sadr, hcs::kCmdRead, fault), now};
    ReadOutcome out = modules.front()->read(q->firstId, q->count);
    if (!out.ok())
        return {exception(q->tadr, q->sadr, hcs::kCmdRead, out.exception), now};
    return {hcs::encode(hcs::ReadResponse{q->tadr, q->sadr, std::move(out.values)}).value(), now};
}

TimedBytes HcsNode::write(std::span<const std::uint8_t> request)
{
    const std::int64_t now = m_clock.nowUs();
    const auto q = hcs::decodeWriteRequest(request, {m_family, true});
    if (!q)
        return {exception(request[0], request[1], hcs::kCmdWrite, exce::kBufferTooSmall), now};
    const auto modules = modulesAt(q->sadr);
    if (modules.empty())
        return {exception(q->tadr, q->sadr, hcs::kCmdWrite, exce::kSlaveTimeout), now};
    if (const std::uint8_t fault = addressFault(modules.size()))
        return {exception(q->tadr, q->sadr, hcs::kCmdWrite, fault), now};
    const WriteOutcome out = modules.front()->write(q->id, q->value);
    if (!out.ok())
        return {exception(q->tadr, q->sadr, hcs::kCmdWrite, out.exception), out.readyAtUs};
    // OPAT manual §2.5 / DMA Profinet manual §3.5: the request echoed.
    return {hcs::encode(hcs::WriteResponse{q->tadr, q->sadr, q->id, q->value}), out.readyAtUs};
}

TimedBytes HcsNode::cyclic(std::span<const std::uint8_t> request)
{
    const std::int64_t now = m_clock.nowUs();
    const std::uint8_t tadr = request[0];
    const auto error = [&](std::uint8_t sadr, std::uint8_t code) {
        return TimedBytes{exception(tadr, sadr, hcs::kCmdCyclic, code), now};
    };
    // OPAT manual §3.1: SNUM 0..7 (+ master); DMA Profinet manual §4.1: SNUM 1..5.
    const auto count = hcs::modulesForSnum(m_family, request[1]);
    if (!count)
        return error(0, exce::kInvalidSlaveCount);
    const std::size_t needed = hcs::kCyclicHeaderSize + hcs::kCyclicModuleSize * *count;
    if (request.size() < needed ||
        (m_options.outputBufferBytes != 0 && m_options.outputBufferBytes < needed))
        return error(0, exce::kBufferTooSmall); // DMA Profinet manual §4.3 code 9: "SADR = 0"
    const auto q = hcs::decodeCyclicRequest(request.first(needed), {m_family, false});
    if (!q)
        return error(0, exce::kInvalidSlaveCount);

    std::vector<HcsModule *> targets;
    for (std::size_t i = 0; i < *count; ++i) {
        const std::uint8_t address = hcs::moduleAddress(m_family, i);
        const auto modules = modulesAt(address);
        // OPAT manual §3.3 / DMA Profinet manual §4.3 example: "Module 3 is not installed and
        // SNUM … is set to 3" → SADR 3, EXCE 8.
        if (modules.empty())
            return error(address, exce::kCyclicSlaveTimeout);
        if (const std::uint8_t fault = addressFault(modules.size()))
            return error(address, fault);
        targets.push_back(modules.front());
    }
    // "Here for multi slave operation the number of present slaves has to be set properly."
    if (cyclicCapable() != *count)
        return error(0, exce::kInvalidSlaveCount);
    // "The data of the write command will be immediately forwarded to all slaves" (§4.4.2).
    for (std::size_t i = 0; i < *count; ++i)
        if (const std::uint8_t code = targets[i]->applyCyclic(q->modules[i]))
            return error(hcs::moduleAddress(m_family, i), code);

    const std::size_t index = m_nextResponder % *count;
    m_nextResponder = (index + 1) % *count;
    const CyclicValues v = targets[index]->cyclicValues();
    return {hcs::encode(hcs::CyclicResponse{tadr, hcs::moduleAddress(m_family, index), v.status,
                                            v.value1, v.value2}),
            now};
}

} // namespace vt::dev::sim
