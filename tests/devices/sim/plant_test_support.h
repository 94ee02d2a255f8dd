// Shared helpers of the plant tests: a parameter store filled with a
// family's defaults, and a clock-driven rig around one plant.
#pragma once

#include "sim/closed_loop_plant.h"
#include "sim/open_loop_plant.h"
#include "sim/param_io.h"
#include "sim/sim_clock.h"
#include "sim_dictionaries.h"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace vt::dev::sim::test {

// One closed-loop branch on a clock; the same ParamMemory is source (C/E/r/A rows) and sink
// (d rows), as in a module's parameter image.
struct ClosedRig
{
    const Dictionary &dict;
    ParamMemory params;
    SimClock clock;
    std::unique_ptr<ClosedLoopPlant> plant;

    explicit ClosedRig(const std::string &name, std::unique_ptr<AxisModel> axis = nullptr,
                       int branch = 1)
        : dict(family(name)), params(dict)
    {
        PlantConfig config;
        config.branch = branch;
        plant = std::make_unique<ClosedLoopPlant>(dict, params, params, std::move(axis), config);
        clock.attach(*plant);
    }
    void set(const std::string &name, std::int32_t raw)
    {
        ASSERT_TRUE(params.set(name, raw)) << dict.family << " has no " << name;
    }
    std::int32_t get(const std::string &name) const { return params.get(name); }
    void run(double seconds) { clock.advance(static_cast<std::int64_t>(seconds * 1e6)); }
    // Samples a display row every millisecond for `seconds`.
    std::vector<std::int32_t> record(const std::string &name, double seconds)
    {
        std::vector<std::int32_t> out;
        const auto n = static_cast<int>(seconds * 1000.0);
        for (int i = 0; i < n; ++i) {
            clock.advance(1000);
            out.push_back(get(name));
        }
        return out;
    }
};

struct OpenRig
{
    const Dictionary &dict;
    ParamMemory params;
    SimClock clock;
    std::unique_ptr<OpenLoopPlant> plant;

    explicit OpenRig(const std::string &name) : dict(family(name)), params(dict)
    {
        plant = std::make_unique<OpenLoopPlant>(dict, params, params);
        clock.attach(*plant);
    }
    void set(const std::string &name, std::int32_t raw)
    {
        ASSERT_TRUE(params.set(name, raw)) << dict.family << " has no " << name;
    }
    std::int32_t get(const std::string &name) const { return params.get(name); }
    void run(double seconds) { clock.advance(static_cast<std::int64_t>(seconds * 1e6)); }
};

} // namespace vt::dev::sim::test
