#include "sim_hart.h"

#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/sim_clock.h"

namespace vt::model {

struct SimHart
{
    SimHart(dev::sim::SimClock &c, const dev::Dictionary &sd7)
        : clock(c), device(std::make_unique<dev::sim::HartDevice>(sd7)),
          server(std::make_shared<dev::sim::HartServer>(*device))
    {
        clock.attach(*device);
    }
    ~SimHart() { clock.detach(*device); }
    SimHart(const SimHart &) = delete;
    SimHart &operator=(const SimHart &) = delete;

    dev::sim::SimClock &clock;
    std::unique_ptr<dev::sim::HartDevice> device;
    std::shared_ptr<dev::sim::HartServer> server;
};

std::shared_ptr<SimHart> makeSimHart(dev::sim::SimClock &clock, const dev::Dictionary &sd7)
{
    return std::make_shared<SimHart>(clock, sd7);
}

std::shared_ptr<dev::ByteServer> hartServer(const SimHart &hart)
{
    return hart.server;
}

dev::sim::HartDevice *hartDevice(const SimHart &hart)
{
    return hart.device.get();
}

} // namespace vt::model
