// SimEndpoint: the built-in simulator as a link — a simulated HCS node or Wandfluh SD7 behind the
// front end of the chosen protocol (dev::sim::SimDevice), driven in real time, reached through a
// SimLink.
// It is what `valvetune --simulate` and `valvetune-cli --sim` connect to, and what the session's
// end-to-end tests talk to (STYLE.md rule 8: the simulator is just another link).
// Ownership: makeSimLink() returns the SimLink; the endpoint is the link's child QObject, so the
// device lives exactly as long as the link. GUI thread (the link's).
#pragma once

#include "access/dsp408_adapter.h"
#include "core/link_protocol.h"
#include "core/result.h"
#include "dict/device_protocol.h"
#include "sim/sim_clock.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <optional>
#include <string>

namespace vt::dev {
class DictionarySet;
namespace sim {
class HcsNode;
class HartDevice;
class Dsp408Device;
class SimDevice;
} // namespace sim
} // namespace vt::dev

namespace vt::link {
class SimLink;
}

namespace vt::model {

struct SimSpec
{
    std::string family;      // dictionary family: "opat", "dma-pn-v51", "wandfluh-sd7" …
    std::size_t modules = 1; // HCS node size
    int mode = 0;            // E00; 0: the family's first mode
    // HCS: false starts a commissioned machine (dev::sim commissioned_preset.h), true the bare
    // dictionary defaults (`--factory`).
    bool factory = false;
    // Modbus RTU, Modbus TCP, the node image, HART (the SD7's only one), dsp408-image or
    // dsp408-gateway (the ED1); nullopt: the family's default (dev::sim::defaultSimProtocol).
    std::optional<dev::LinkProtocol> protocol;
    int baudRate = 0; // simulated wire speed; 0: no wire delay
    int bitsPerCharacter = 11;
    // The ED1's image layout and gateway registers (dsp408-image, dsp408-gateway); the master
    // must use the same (ConnectionSpec::dsp408 is copied here for a simulator connection).
    dev::access::Dsp408LinkOptions dsp408;
};

// Whether a SimLink can carry a device of this protocol: every family is served as a byte
// stream — HCS nodes, the SD7's HART, the ED1's PROFIBUS image (raw or behind a gateway's
// Modbus TCP registers). Only CANopen frames need a CAN socket.
bool servedOverSimLink(dev::DeviceProtocol device);

// "dma-pn-v51:3" → family and module count; an error names what is wrong.
dev::Result<SimSpec, QString> parseSimSpec(const QString &text);

class SimEndpoint : public QObject
{
    Q_OBJECT
public:
    ~SimEndpoint() override;

    dev::sim::SimClock &clock() { return m_clock; }
    dev::sim::HcsNode *node() const;     // HCS families
    dev::sim::HartDevice *hart() const;  // wandfluh-sd7
    dev::sim::Dsp408Device *ed1() const; // wandfluh-ed1
    const SimSpec &spec() const { return m_spec; }
    // The module address a master uses for module `index` (Modbus unit / node SADR / poll address).
    int moduleAddress(std::size_t index) const;
    std::size_t moduleCount() const;

    // Real time (the default): a 1 ms timer moves the simulated clock with the wall clock.
    void setRunning(bool running);

private:
    friend dev::Result<std::unique_ptr<link::SimLink>, QString>
    makeSimLink(const SimSpec &spec, const dev::DictionarySet *set);
    SimEndpoint(SimSpec spec, QObject *parent);
    void tick();

    SimSpec m_spec;
    dev::sim::SimClock m_clock;
    std::shared_ptr<dev::sim::SimDevice> m_device; // shared with the link (its server)
    link::SimLink *m_link = nullptr;
    QTimer m_timer;
    QElapsedTimer m_elapsed;
    std::int64_t m_offsetUs = 0;
};

// Builds the device and its link (not yet open). `set`: the dictionaries (builtin when null),
// which must outlive the link. The endpoint is `link->findChild<SimEndpoint *>()`.
dev::Result<std::unique_ptr<link::SimLink>, QString>
makeSimLink(const SimSpec &spec, const dev::DictionarySet *set = nullptr);
SimEndpoint *simEndpointOf(const link::SimLink &link);

} // namespace vt::model
