#include "node_rules.h"

#include "exceptions.h"

#include <algorithm>
#include <string>

namespace vt::dev::hcs {
namespace {

std::string n(unsigned v)
{
    return std::to_string(v);
}

// OPAT manual §2.1: "0 = standard (OPAT-Master) … 1 to 7 = OPAT-Slave"; DMA Profinet manual §3.1:
// "1 = standard (single slave), 2 to 32 = also possible (E22 defines the slave address)".
void checkSadr(std::vector<LocalText> &notes, std::uint8_t sadr, Family family)
{
    if (family == Family::Opat && sadr > 7)
        notes.push_back(
            {"SADR " + n(sadr) +
                 " is outside 0..7: 0 = OPAT master, 1..7 = OPAT CAN slaves (OPAT manual §2.1)",
             "SADR " + n(sadr) +
                 " liegt außerhalb 0..7: 0 = OPAT-Master, 1..7 = OPAT-CAN-Slaves (OPAT manual "
                 "§2.1)"});
    if (family == Family::Dma && (sadr < 1 || sadr > 32))
        notes.push_back(
            {"SADR " + n(sadr) + " is outside 1..32, the range of E22 (DMA Profinet manual §3.1)",
             "SADR " + n(sadr) +
                 " liegt außerhalb 1..32, dem Bereich von E22 (DMA Profibus Anleitung §3.1)"});
}

} // namespace

std::vector<ReadBlock> splitReads(std::uint16_t firstId, std::uint32_t count,
                                  std::uint16_t maxPerBlock)
{
    std::vector<ReadBlock> blocks;
    const std::uint32_t step = std::max<std::uint32_t>(maxPerBlock, 1);
    std::uint32_t id = firstId;
    std::uint32_t left = std::min<std::uint32_t>(count, 0x10000u - id);
    while (left > 0) {
        const std::uint32_t take = std::min(left, step);
        blocks.push_back({static_cast<std::uint16_t>(id), static_cast<std::uint16_t>(take)});
        id += take;
        left -= take;
    }
    return blocks;
}

std::vector<LocalText> nodeRuleNotes(const Request &request, Family family)
{
    std::vector<LocalText> notes;
    if (const auto *q = std::get_if<ReadRequest>(&request)) {
        checkSadr(notes, q->sadr, family);
        if (!withinReadLimit(q->count))
            notes.push_back({"N = " + n(q->count) +
                                 ": the node reads 1..8 parameters at once and answers exception 3 "
                                 "(OPAT manual §2.1)",
                             "N = " + n(q->count) +
                                 ": der Knoten liest 1..8 Parameter auf einmal und antwortet mit "
                                 "Ausnahme 3 (DMA Profibus Anleitung §3.1)"});
    } else if (const auto *w = std::get_if<WriteRequest>(&request)) {
        checkSadr(notes, w->sadr, family);
    }
    return notes;
}

std::vector<LocalText> nodeRuleNotes(const Response &response, Family family)
{
    std::vector<LocalText> notes;
    if (const auto *a = std::get_if<ReadResponse>(&response)) {
        checkSadr(notes, a->sadr, family);
        const std::size_t cnt = a->values.size() * 2;
        if (cnt == 0 || cnt > kMaxReadDataBytes)
            notes.push_back({"CNT " + n(static_cast<unsigned>(cnt)) +
                                 " is outside 2..16 (OPAT manual §2.2: maximal 16 data bytes)",
                             "CNT " + n(static_cast<unsigned>(cnt)) +
                                 " liegt außerhalb 2..16 (DMA Profibus Anleitung §3.2: maximal 16 "
                                 "Daten Bytes)"});
    } else if (const auto *w = std::get_if<WriteResponse>(&response)) {
        checkSadr(notes, w->sadr, family);
    } else if (const auto *c = std::get_if<CyclicResponse>(&response)) {
        const unsigned lo = family == Family::Opat ? 0 : 1;
        const unsigned hi = family == Family::Opat ? 7 : 5;
        if (c->sadr < lo || c->sadr > hi)
            notes.push_back({"SADR " + n(c->sadr) + " cannot answer CMD 15 (modules " + n(lo) +
                                 ".." + n(hi) + ", OPAT manual §1.6 / DMA Profinet manual §1.5)",
                             "SADR " + n(c->sadr) + " kann CMD 15 nicht beantworten (Module " +
                                 n(lo) + ".." + n(hi) + ", DMA Profibus Anleitung §1.5)"});
    } else if (const auto *e = std::get_if<ExceptionResponse>(&response)) {
        if (!exceptionText(family, e->command, e->code))
            notes.push_back({"EXCE " + n(e->code) + " is not in the " +
                                 std::string(familyName(family)) + " exception table",
                             "EXCE " + n(e->code) + " steht nicht in der Ausnahmetabelle (" +
                                 std::string(familyName(family)) + ")"});
    }
    return notes;
}

} // namespace vt::dev::hcs
