// OpenLoopPlant: one branch of a module without a closed loop (mode 1, DMA V13/V15; the open
// loop path of the OPAT): set value → ramps → valve chain → solenoid currents, publishing
// d1.01..d1.09 and detecting set value and output stage errors. Deterministic; a SimModel.
// Owner: the simulated module; it and its ParamSource/ParamSink live on one thread.
#pragma once

#include "sim/plant_errors.h"
#include "sim/set_value_path.h"
#include "sim/sim_clock.h"
#include "sim/valve_chain.h"

namespace vt::dev::sim {

// Everything one branch's plant needs besides the parameter values.
struct PlantConfig
{
    int branch = 1;
    CurrentControllerConstants currents;
};

class OpenLoopPlant : public SimModel
{
public:
    // The dictionary, source and sink must outlive the plant.
    OpenLoopPlant(const Dictionary &dict, const ParamSource &params, ParamSink &display,
                  PlantConfig config = {});

    void step(const SimStep &step) override;

    // Hardware enable together with the bus (software) disable: false switches the outputs off.
    void setEnabled(bool enabled) { m_enabled = enabled; }
    bool enabled() const { return m_enabled; }
    void setAnalogueInput(AnalogueInput input, double physical);
    void setSolenoidFault(bool solenoidB, SolenoidFault fault);

    // Enable off/on, Bus Disable set/reset or OPAT EClr: clears latched errors whose cause has
    // gone.
    bool acknowledgeErrors() { return m_errors.acknowledge(); }
    const ErrorLatch &errors() const { return m_errors; }
    ErrorTable errorTable() const { return m_table; }

    const SetValuePathValues &setValue() const { return m_path.values(); }
    const ValveChainValues &valve() const { return m_chain.values(); }
    ValveChain &chain() { return m_chain; }

private:
    ParamReader m_params;
    ParamPublisher m_out;
    ErrorTable m_table;
    SetValuePath m_path;
    ValveChain m_chain;
    ErrorLatch m_errors;
    bool m_enabled = true;
};

// Output stage errors of a valve chain (DMA Profinet manual §4.5.1.1 errors 3 and 8).
PlantErrors outputStageErrors(const ValveChain &chain);

} // namespace vt::dev::sim
