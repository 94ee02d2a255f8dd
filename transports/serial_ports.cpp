#include "serial_ports.h"

#include "link_log.h"

#include <algorithm>
#include <libserialport.h>

namespace vt::link {

namespace {

QString fromC(const char *text)
{
    return text ? QString::fromLocal8Bit(text) : QString();
}

SerialPortInfo describe(sp_port *port)
{
    SerialPortInfo info;
    info.name = fromC(sp_get_port_name(port));
    info.description = fromC(sp_get_port_description(port));
    switch (sp_get_port_transport(port)) {
    case SP_TRANSPORT_USB: info.transport = SerialTransport::Usb; break;
    case SP_TRANSPORT_BLUETOOTH: info.transport = SerialTransport::Bluetooth; break;
    case SP_TRANSPORT_NATIVE: info.transport = SerialTransport::Native; break;
    }
    if (info.transport == SerialTransport::Usb) {
        int vid = -1;
        int pid = -1;
        if (sp_get_port_usb_vid_pid(port, &vid, &pid) == SP_OK && vid >= 0 && vid <= 0xFFFF &&
            pid >= 0 && pid <= 0xFFFF) {
            info.usbVid = static_cast<std::uint16_t>(vid);
            info.usbPid = static_cast<std::uint16_t>(pid);
        }
        info.manufacturer = fromC(sp_get_port_usb_manufacturer(port));
        info.serialNumber = fromC(sp_get_port_usb_serial(port));
        const QString product = fromC(sp_get_port_usb_product(port));
        if (!product.isEmpty())
            info.description = product;
    }
    if (info.description.isEmpty())
        info.description = info.name.section(QLatin1Char('/'), -1);
    return info;
}

} // namespace

QString SerialPortInfo::displayText() const
{
    QString text = name;
    if (!description.isEmpty() && description != name.section(QLatin1Char('/'), -1))
        text += QStringLiteral(" — ") + description;
    if (usbVid && usbPid) {
        text += QStringLiteral(" (%1:%2)")
                    .arg(*usbVid, 4, 16, QLatin1Char('0'))
                    .arg(*usbPid, 4, 16, QLatin1Char('0'));
    }
    return text;
}

std::vector<SerialPortInfo> availableSerialPorts()
{
    std::vector<SerialPortInfo> ports;
    sp_port **list = nullptr;
    if (sp_list_ports(&list) != SP_OK) {
        char *message = sp_last_error_message();
        qCWarning(lcLink).noquote() << "serial port enumeration failed:" << fromC(message);
        sp_free_error_message(message);
        return ports;
    }
    for (sp_port **it = list; it && *it; ++it)
        ports.push_back(describe(*it));
    sp_free_port_list(list);
    std::sort(ports.begin(), ports.end(),
              [](const SerialPortInfo &a, const SerialPortInfo &b) { return a.name < b.name; });
    return ports;
}

} // namespace vt::link
