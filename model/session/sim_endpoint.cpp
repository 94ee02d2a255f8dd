#include "sim_endpoint.h"

#include "dict/dictionary_loader.h"
#include "sim/sim_device.h"
#include "transports/sim_link.h"

namespace vt::model {

bool servedOverSimLink(dev::DeviceProtocol)
{
    return true;
}

dev::Result<SimSpec, QString> parseSimSpec(const QString &text)
{
    SimSpec spec;
    const QStringList parts = text.split(QLatin1Char(':'));
    if (parts.size() > 2 || parts.front().isEmpty())
        return SimEndpoint::tr("expected FAMILY or FAMILY:MODULES, got '%1'").arg(text);
    spec.family = parts.front().toStdString();
    if (parts.size() == 2) {
        bool ok = false;
        const int n = parts[1].toInt(&ok);
        if (!ok || n < 1 || n > 32)
            return SimEndpoint::tr("module count '%1' is not 1..32").arg(parts[1]);
        spec.modules = static_cast<std::size_t>(n);
    }
    return spec;
}

SimEndpoint::SimEndpoint(SimSpec spec, QObject *parent) : QObject(parent), m_spec(std::move(spec))
{
    m_timer.setInterval(1);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimEndpoint::tick);
}

SimEndpoint::~SimEndpoint() = default;

dev::sim::HcsNode *SimEndpoint::node() const
{
    return m_device ? m_device->node() : nullptr;
}

dev::sim::HartDevice *SimEndpoint::hart() const
{
    return m_device ? m_device->hart() : nullptr;
}

dev::sim::Dsp408Device *SimEndpoint::ed1() const
{
    return m_device ? m_device->ed1() : nullptr;
}

int SimEndpoint::moduleAddress(std::size_t index) const
{
    return m_device ? m_device->moduleAddress(index) : -1;
}

std::size_t SimEndpoint::moduleCount() const
{
    return m_device ? m_device->moduleCount() : 0;
}

void SimEndpoint::setRunning(bool running)
{
    if (running == m_timer.isActive())
        return;
    if (running) {
        m_offsetUs = m_clock.nowUs();
        m_elapsed.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
}

void SimEndpoint::tick()
{
    m_clock.advanceTo(m_offsetUs + m_elapsed.nsecsElapsed() / 1000);
    if (m_link)
        m_link->pump();
}

dev::Result<std::unique_ptr<link::SimLink>, QString> makeSimLink(const SimSpec &spec,
                                                                 const dev::DictionarySet *set)
{
    if (!set) {
        const auto &builtin = dev::builtinDictionaries();
        if (!builtin.ok())
            return SimEndpoint::tr("the built-in dictionaries do not load");
        set = &*builtin;
    }
    const QString family = QString::fromStdString(spec.family);
    const dev::Dictionary *dict = set->find(spec.family);
    if (!dict)
        return SimEndpoint::tr("unknown device family '%1'").arg(family);
    const auto notServed = [&](dev::LinkProtocol protocol) {
        if (dict->protocol == dev::DeviceProtocol::Hart)
            return SimEndpoint::tr("%1 speaks HART only").arg(family);
        if (dict->protocol == dev::DeviceProtocol::Dsp408)
            return SimEndpoint::tr("%1 is simulated over its PROFIBUS image: dsp408-image or "
                                   "dsp408-gateway")
                .arg(family);
        return SimEndpoint::tr("the simulator does not serve %1 over '%2'")
            .arg(family, QString::fromLatin1(dev::key(protocol)));
    };
    if (spec.protocol == dev::LinkProtocol::Canopen)
        return notServed(*spec.protocol);

    auto endpoint = std::unique_ptr<SimEndpoint>(new SimEndpoint(spec, nullptr));
    dev::sim::SimDeviceSpec deviceSpec;
    deviceSpec.family = spec.family;
    deviceSpec.modules = spec.modules;
    deviceSpec.mode = spec.mode;
    deviceSpec.factory = spec.factory;
    deviceSpec.protocol = spec.protocol;
    deviceSpec.dsp408 = spec.dsp408;
    auto device = dev::sim::SimDevice::build(endpoint->m_clock, *set, deviceSpec);
    if (!device.ok()) {
        const dev::sim::SimBuildError &error = device.error();
        switch (error.code) {
        case dev::sim::SimBuildErrc::UnknownFamily:
            return SimEndpoint::tr("unknown device family '%1'").arg(family);
        case dev::sim::SimBuildErrc::BadNode: return QString::fromStdString(error.message);
        case dev::sim::SimBuildErrc::NotServed:
            return notServed(spec.protocol.value_or(dev::LinkProtocol::Canopen));
        }
    }
    endpoint->m_device = std::move(device).value();
    endpoint->m_spec.protocol = endpoint->m_device->protocol(); // the protocol the simulator chose

    // The link shares the device: the server it drives is part of it.
    std::shared_ptr<dev::ByteServer> server(endpoint->m_device, &endpoint->m_device->server());
    auto link = std::make_unique<link::SimLink>(std::move(server), family);
    if (spec.baudRate > 0)
        link->setWireTiming(spec.baudRate, spec.bitsPerCharacter);
    endpoint->m_link = link.get();
    endpoint->setParent(link.get());
    endpoint.release()->setRunning(true);
    return link;
}

SimEndpoint *simEndpointOf(const link::SimLink &link)
{
    return link.findChild<SimEndpoint *>(QString(), Qt::FindDirectChildrenOnly);
}

} // namespace vt::model
