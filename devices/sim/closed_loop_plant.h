// ClosedLoopPlant: one closed-loop branch (modes 3/4: DMA V51, DMA V31/V32; OPAT modes 3/4/6/8,
// branch 2 with the C2/d2 rows): set value path → P-PT1-I-DT1 controller → valve chain →
// valve → axis → feedback sensor, publishing d1.01..d1.13 (d2.xx) and detecting feedback cable
// fracture, set value and output stage errors. Deterministic; a SimModel.
// Owner: the simulated module; it and its ParamSource/ParamSink live on one thread.
#pragma once

#include "sim/axis_model.h"
#include "sim/feedback_sensor.h"
#include "sim/loop_controller.h"
#include "sim/open_loop_plant.h"

#include <memory>

namespace vt::dev::sim {

struct ClosedLoopIds
{
    ParamRef controller;                                           // C1.00
    ParamRef sensor, feedbackGain, feedbackOffset, feedbackSign;   // C1.09..C1.12
    ParamRef kp1, pt1Time, threshold, kp2, ki, kd, dt1Time, pGain; // C1.13..C1.20
    ParamRef fractureDetection;                                    // C1.26
    ParamRef iLimit;                                               // C1.33
    ParamRef negativeGain;                                         // C1.36 (OPAT)
    ParamRef busFeedback;                                          // A1.02
    ParamRef desired, actual, lagError, output;                    // d1.10..d1.13

    static ClosedLoopIds resolve(const Dictionary &dict, int branch);
};

struct LoopValues
{
    double desired = 0;  // d1.10 (w)
    double actual = 0;   // d1.11 (x)
    double lagError = 0; // d1.12 (e = w − x)
    double output = 0;   // d1.13 (y)
    bool closed = false; // the loop is closed now (Dout_1 for the remote loop controller)
};

class ClosedLoopPlant : public SimModel
{
public:
    // The dictionary, source and sink must outlive the plant; the plant owns the axis.
    ClosedLoopPlant(const Dictionary &dict, const ParamSource &params, ParamSink &display,
                    std::unique_ptr<AxisModel> axis, PlantConfig config = {},
                    ValveConstants valve = {});

    void step(const SimStep &step) override;

    void setEnabled(bool enabled) { m_enabled = enabled; }
    bool enabled() const { return m_enabled; }
    // Din_1 / Din_2 (ID 0xB0, CMD 15 special function byte): enables the remote loop controller.
    void setDin(bool din) { m_din = din; }
    void setAnalogueInput(AnalogueInput input, double physical);
    void setSolenoidFault(bool solenoidB, SolenoidFault fault);
    void setSensorFault(SensorFault fault) { m_sensorFault = fault; }

    bool acknowledgeErrors() { return m_errors.acknowledge(); }
    const ErrorLatch &errors() const { return m_errors; }
    ErrorTable errorTable() const { return m_table; }
    int branch() const { return m_branch; }

    const SetValuePathValues &setValue() const { return m_path.values(); }
    const ValveChainValues &valve() const { return m_chain.values(); }
    const LoopValues &loop() const { return m_loop; }
    const LoopController &controller() const { return m_controller; }
    AxisModel &axis() { return *m_axis; }
    const ValveModel &valveModel() const { return m_valve; }

    LoopSettings loopSettings() const;
    FeedbackSettings feedbackSettings() const;

private:
    bool loopWanted(bool outputsOn) const;

    ParamReader m_params;
    ParamPublisher m_out;
    ErrorTable m_table;
    int m_branch;
    ClosedLoopIds m_ids;
    SetValuePath m_path;
    ValveChain m_chain;
    LoopController m_controller;
    ValveModel m_valve;
    std::unique_ptr<AxisModel> m_axis;
    ErrorLatch m_errors;
    LoopValues m_loop;
    SensorFault m_sensorFault = SensorFault::None;
    bool m_enabled = true;
    bool m_din = false;
};

} // namespace vt::dev::sim
