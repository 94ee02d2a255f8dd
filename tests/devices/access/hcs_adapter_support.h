// Shared helpers of the HCS adapter tests (node image, Modbus RTU / TCP, CANopen 0x2000 + ID):
// rows of a simulated module to write, to refuse, the value the module holds for a row, and a
// module's first read block as the simulator answers it.
#pragma once

#include "../sim/hcs_sim_support.h"
#include "access/hcs_rows.h"
#include "adapter_rig.h"
#include "sim/hcs_module.h"

#include <string>
#include <vector>

namespace vt::dev::access::test {

// A row the bus may change freely: read/write, a real range, no limit taken from another row,
// not the address (E22), the mode (E00) or the state word (0xB0).
inline const ParamMeta *writableRow(const sim::HcsModule &module)
{
    for (const ParamMeta *row : sim::test::readableRows(module)) {
        if (row->writable() && row->min < row->max && row->minParam.empty() &&
            row->maxParam.empty() && row->name != "E22" && row->name != "E00" &&
            row->name != "0xB0")
            return row;
    }
    ADD_FAILURE() << "no writable row";
    return nullptr;
}

// A writable row whose maximum is below its type's, so max + 1 still fits the telegram.
inline const ParamMeta *boundedRow(const sim::HcsModule &module)
{
    for (const ParamMeta *row : sim::test::readableRows(module)) {
        if (row->writable() && row->max < typeMax(row->type) && row->maxParam.empty() &&
            row->name != "E22" && row->name != "E00")
            return row;
    }
    ADD_FAILURE() << "no bounded row";
    return nullptr;
}

// The row's value now, as the module's image holds it (the word the telegram carries).
inline double storedRaw(const sim::HcsModule &module, const ParamMeta &row)
{
    return registerToRaw(row, module.storage().word(*row.id));
}

// A value in range that differs from the present one.
inline double otherValue(const sim::HcsModule &module, const ParamMeta &row)
{
    return storedRaw(module, row) != row.min ? row.min : row.max;
}

// A module's first read block: the transaction, the simulator's answer and the values it carries.
struct ReadBlock
{
    Transaction t;
    Bytes answer;
    std::vector<RawValue> truth;
};

inline ReadBlock firstReadBlock(Rig &rig, const sim::HcsModule &module)
{
    ReadBlock block{
        rig.adapter.planRead(module.address(), sim::test::readableRows(module)).front(), {}, {}};
    block.answer = rig.ask(rig.adapter.encode(block.t));
    for (const ParamMeta *row : block.t.rows)
        block.truth.emplace_back(storedRaw(module, *row));
    return block;
}

} // namespace vt::dev::access::test
