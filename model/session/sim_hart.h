// The SD7 HART simulator for SimEndpoint, behind an opaque handle: its Qt-free headers use
// names Qt's keyword macros take (hart::DeviceVariables::slots), so only sim_hart.cpp, which
// includes no Qt header, sees them.
#pragma once

#include <memory>

namespace vt::dev {
class ByteServer;
struct Dictionary;
namespace sim {
class HartDevice;
class SimClock;
} // namespace sim
} // namespace vt::dev

namespace vt::model {

struct SimHart;

// Builds the device on `clock` (attached until the handle is gone) and its HART front end.
std::shared_ptr<SimHart> makeSimHart(dev::sim::SimClock &clock, const dev::Dictionary &sd7);
std::shared_ptr<dev::ByteServer> hartServer(const SimHart &hart);
dev::sim::HartDevice *hartDevice(const SimHart &hart);

} // namespace vt::model
