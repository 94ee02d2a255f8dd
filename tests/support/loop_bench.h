// A position loop on the built-in simulator for the workbench's tests: a DMA PROFINET module
// (mode 3) commissioned by confirmed writes as docs/SIMULATOR-PLANT.md's tests set it up —
// P-PT1-I-DT1 controller (C1.00 = 1), a 0 … 10 V position sensor (C1.09 = 4), the set value from
// the bus only (E17 = 2) — and step tests of A1.01 3 V → 5 V recorded with d1.10 and d1.11.
#pragma once

#include "model/tuning/run_analysis.h"
#include "model/tuning/test_run.h"
#include "sim_rig.h"

#include <gtest/gtest.h>

namespace vt::test {

struct LoopBench
{
    std::unique_ptr<SimRig> rig = connectSim({"dma-pn-v51", 1, {}, {}, {}});

    bool write(const char *name, double raw)
    {
        std::optional<model::Outcome> done;
        rig->access().write(rig->module().address, rig->row(name), dev::RawValue{raw},
                            model::Priority::User, std::nullopt,
                            [&](const model::Outcome &o) { done = o; });
        if (!waitFor(done))
            return false;
        // DMA Profinet manual §3.4.1: an EEPROM write needs up to 25 ms; the module refuses the
        // next one before (the product paces its own writes, WriteJob).
        if (rig->row(name).persistence != dev::Persistence::Volatile)
            spinFor(rig->module().dictionary->writePacingMs + 5);
        EXPECT_EQ(done->status, model::OutcomeStatus::Ok) << name;
        return done->status == model::OutcomeStatus::Ok;
    }
    double read(const char *name) { return rig->read(name).value_or(NAN); }

    // The loop with P gain `kp` (C1.13 raw, 100 == 1.00) and I portion `ki` (C1.17 raw), held at
    // the step's start value 3 V.
    bool positionLoop(double kp, double ki)
    {
        return rig && write("E17", 2) && write("C1.00", 1) && write("C1.09", 4) &&
               write("C1.13", kp) && write("C1.17", ki) && write("A1.01", 3000);
    }

    static model::SignalSpec upStep(double hold)
    {
        model::SignalSpec s;
        s.kind = model::SignalKind::Step;
        s.from = 3;
        s.to = 5;
        s.hold = hold;
        return s;
    }
    std::vector<const dev::ParamMeta *> channels() const
    {
        return {&rig->row("d1.10"), &rig->row("d1.11")};
    }
};

} // namespace vt::test
