#include "connection_memory.h"

#include <QSettings>

namespace vt::ui {

namespace {

using model::ConnectionKind;

constexpr ConnectionKind kKinds[] = {ConnectionKind::Serial, ConnectionKind::Tcp,
                                     ConnectionKind::Can, ConnectionKind::Hart,
                                     ConnectionKind::Sim};

std::optional<ConnectionKind> kindOfKey(const QString &key)
{
    for (ConnectionKind kind : kKinds)
        if (key == QLatin1String(model::connectionKindKey(kind)))
            return kind;
    return std::nullopt;
}

const char *productKey(dev::HcsProduct product)
{
    switch (product) {
    case dev::HcsProduct::Unknown: return "unknown";
    case dev::HcsProduct::Opat: return "opat";
    case dev::HcsProduct::DmaProfinet: return "dma-pn";
    case dev::HcsProduct::DmaProfibus: return "dma-pb";
    }
    return "unknown";
}

dev::HcsProduct productOfKey(const QString &key)
{
    for (dev::HcsProduct p :
         {dev::HcsProduct::Opat, dev::HcsProduct::DmaProfinet, dev::HcsProduct::DmaProfibus})
        if (key == QLatin1String(productKey(p)))
            return p;
    return dev::HcsProduct::Unknown;
}

// The link protocol saved in the current group; nullopt when none (or an unknown one) is saved.
std::optional<dev::LinkProtocol> storedProtocol(const QSettings &s)
{
    return dev::fromKey<dev::LinkProtocol>(
        s.value(QStringLiteral("protocol")).toString().toStdString());
}

// Group guard: settings.beginGroup("connection/<kind>") … endGroup(), also on early return.
class Group
{
public:
    Group(QSettings &settings, const QString &name) : m_settings(settings)
    {
        m_settings.beginGroup(name);
    }
    ~Group() { m_settings.endGroup(); }
    Group(const Group &) = delete;
    Group &operator=(const Group &) = delete;

private:
    QSettings &m_settings;
};

QString groupOf(ConnectionKind kind)
{
    return QStringLiteral("connection/") + QLatin1String(model::connectionKindKey(kind));
}

} // namespace

void ConnectionMemory::save(const model::ConnectionSpec &spec)
{
    m_settings.setValue(QStringLiteral("connection/lastKind"),
                        QLatin1String(model::connectionKindKey(spec.kind)));
    m_settings.remove(groupOf(spec.kind));
    const Group group(m_settings, groupOf(spec.kind));
    QSettings &s = m_settings;
    switch (spec.kind) {
    case ConnectionKind::Serial:
        s.setValue(QStringLiteral("port"), spec.serial.portName);
        s.setValue(QStringLiteral("baud"), spec.serial.baudRate);
        s.setValue(QStringLiteral("format"), spec.serial.formatText());
        break;
    case ConnectionKind::Hart: s.setValue(QStringLiteral("port"), spec.serial.portName); break;
    case ConnectionKind::Tcp:
        s.setValue(QStringLiteral("host"), spec.host);
        s.setValue(QStringLiteral("port"), spec.port);
        s.setValue(QStringLiteral("protocol"), QLatin1String(dev::key(spec.tcpProtocol)));
        if (dev::isDsp408Link(spec.tcpProtocol)) {
            const auto &g = spec.dsp408.gateway;
            s.setValue(QStringLiteral("outputRegister"), g.outputRegister);
            s.setValue(QStringLiteral("inputRegister"), g.inputRegister);
            s.setValue(QStringLiteral("inputFunction"), static_cast<int>(g.inputFunction));
            s.setValue(QStringLiteral("firstByteLow"),
                       g.byteOrder == dev::dsp408::RegisterByteOrder::FirstByteLow);
            s.setValue(QStringLiteral("lowWordFirst"),
                       spec.dsp408.layout.pzdWordOrder == dev::dsp408::WordOrder::LowWordFirst);
            s.setValue(QStringLiteral("indByte3"),
                       spec.dsp408.layout.indPosition == dev::dsp408::IndPosition::Byte3);
        }
        break;
    case ConnectionKind::Can:
        s.setValue(QStringLiteral("interface"), spec.canInterface);
        s.setValue(QStringLiteral("node"), spec.canNode);
        s.setValue(QStringLiteral("dsp408"), spec.canDsp408);
        break;
    case ConnectionKind::Sim:
        s.setValue(QStringLiteral("family"), QString::fromStdString(spec.sim.family));
        s.setValue(QStringLiteral("modules"), static_cast<int>(spec.sim.modules));
        s.setValue(QStringLiteral("mode"), spec.sim.mode);
        if (spec.sim.protocol)
            s.setValue(QStringLiteral("protocol"), QLatin1String(dev::key(*spec.sim.protocol)));
        break;
    }
    if (spec.unit)
        s.setValue(QStringLiteral("unit"), *spec.unit);
    if (spec.product != dev::HcsProduct::Unknown)
        s.setValue(QStringLiteral("product"), QLatin1String(productKey(spec.product)));
}

std::optional<model::ConnectionSpec> ConnectionMemory::load(ConnectionKind kind) const
{
    const Group group(m_settings, groupOf(kind));
    const QSettings &s = m_settings;
    if (s.childKeys().isEmpty())
        return std::nullopt;
    model::ConnectionSpec spec;
    spec.kind = kind;
    switch (kind) {
    case ConnectionKind::Serial:
        spec.serial = link::SerialSettings::hcsDefault(s.value(QStringLiteral("port")).toString());
        spec.serial.baudRate = s.value(QStringLiteral("baud"), spec.serial.baudRate).toInt();
        // A damaged format keeps the HCS default (setFormatText changes nothing on failure).
        spec.serial.setFormatText(s.value(QStringLiteral("format")).toString());
        break;
    case ConnectionKind::Hart:
        spec.serial = link::SerialSettings::hart(s.value(QStringLiteral("port")).toString());
        break;
    case ConnectionKind::Tcp:
        spec.host = s.value(QStringLiteral("host")).toString();
        spec.port = static_cast<quint16>(s.value(QStringLiteral("port"), spec.port).toUInt());
        spec.tcpProtocol = storedProtocol(s).value_or(dev::LinkProtocol::ModbusTcp);
        if (spec.tcpProtocol != dev::LinkProtocol::NodeImage &&
            !dev::isDsp408Link(spec.tcpProtocol))
            spec.tcpProtocol = dev::LinkProtocol::ModbusTcp;
        if (dev::isDsp408Link(spec.tcpProtocol)) {
            auto &g = spec.dsp408.gateway;
            g.outputRegister = static_cast<std::uint16_t>(
                s.value(QStringLiteral("outputRegister"), g.outputRegister).toUInt());
            g.inputRegister = static_cast<std::uint16_t>(
                s.value(QStringLiteral("inputRegister"), g.inputRegister).toUInt());
            g.inputFunction = s.value(QStringLiteral("inputFunction")).toInt() == 4
                                  ? dev::dsp408::InputFunction::InputRegisters
                                  : dev::dsp408::InputFunction::HoldingRegisters;
            if (s.value(QStringLiteral("firstByteLow"), false).toBool())
                g.byteOrder = dev::dsp408::RegisterByteOrder::FirstByteLow;
            if (s.value(QStringLiteral("lowWordFirst"), false).toBool())
                spec.dsp408.layout.pzdWordOrder = dev::dsp408::WordOrder::LowWordFirst;
            if (s.value(QStringLiteral("indByte3"), false).toBool())
                spec.dsp408.layout.indPosition = dev::dsp408::IndPosition::Byte3;
        }
        break;
    case ConnectionKind::Can:
        spec.canInterface = s.value(QStringLiteral("interface")).toString();
        spec.canNode = s.value(QStringLiteral("node"), spec.canNode).toInt();
        spec.canDsp408 = s.value(QStringLiteral("dsp408"), false).toBool();
        break;
    case ConnectionKind::Sim:
        spec.sim.family = s.value(QStringLiteral("family")).toString().toStdString();
        spec.sim.modules =
            static_cast<std::size_t>(std::max(1, s.value(QStringLiteral("modules"), 1).toInt()));
        spec.sim.mode = s.value(QStringLiteral("mode"), 0).toInt();
        spec.sim.protocol = storedProtocol(s);
        break;
    }
    bool ok = false;
    const int unit = s.value(QStringLiteral("unit")).toInt(&ok);
    if (ok)
        spec.unit = unit;
    spec.product = productOfKey(s.value(QStringLiteral("product")).toString());
    return spec;
}

std::optional<ConnectionKind> ConnectionMemory::lastKind() const
{
    return kindOfKey(m_settings.value(QStringLiteral("connection/lastKind")).toString());
}

} // namespace vt::ui
