#include "serial_page.h"

#include "widgets/connect/hcs_product_box.h"
#include "widgets/connect/serial_line_fields.h"
#include "widgets/connect/serial_port_box.h"
#include "widgets/number_box.h"

#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace vt::ui {

namespace {

// Modbus: unit 0 is the broadcast address no module answers; 1..247 are unit addresses.
constexpr int kMaxUnit = 247;

} // namespace

SerialPage::SerialPage(QWidget *parent) : ConnectPage(parent)
{
    setObjectName(QStringLiteral("serialPage"));
    auto *form = new QFormLayout(this);
    m_port = new SerialPortBox(QStringLiteral("serial"), this);
    m_portLabel = new QLabel(this);
    form->addRow(m_portLabel, m_port);
    m_line = new SerialLineFields(QStringLiteral("serial"), form, this);
    m_address = new WholeNumberBox(this);
    m_address->setObjectName(QStringLiteral("serialAddress"));
    // 0 is typeable so that problem() can say why it does not work.
    m_address->setRange(0, kMaxUnit);
    m_address->setValue(1);
    m_addressLabel = new QLabel(this);
    form->addRow(m_addressLabel, m_address);
    m_product = new HcsProductBox(this);
    m_product->setObjectName(QStringLiteral("serialProduct"));
    m_productLabel = new QLabel(this);
    form->addRow(m_productLabel, m_product);

    connect(m_port, &SerialPortBox::changed, this, &ConnectPage::changed);
    connect(m_line, &SerialLineFields::changed, this, &ConnectPage::changed);
    connect(m_address, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    connect(m_product, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    retranslate();
}

QString SerialPage::title() const
{
    return tr("Serial (Modbus RTU)");
}

void SerialPage::load(const model::ConnectionSpec &spec)
{
    m_port->setPortName(spec.serial.portName);
    m_line->setSettings(spec.serial);
    m_silentInterval = spec.serial.silentInterval;
    m_frameEndBySilence = spec.serial.frameEndBySilence;
    m_address->setValue(spec.unit.value_or(1));
    m_product->setProduct(spec.product);
}

model::ConnectionSpec SerialPage::spec() const
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Serial;
    spec.serial = m_line->settings(m_port->portName());
    spec.serial.silentInterval = m_silentInterval;
    spec.serial.frameEndBySilence = m_frameEndBySilence;
    spec.unit = m_address->value();
    spec.product = m_product->product();
    return spec;
}

QString SerialPage::problem() const
{
    if (m_port->portName().isEmpty())
        return tr("Choose a serial port or type its path.");
    if (const QString line = m_line->problem(); !line.isEmpty())
        return line;
    if (m_address->value() == 0)
        return tr("Module address 0 is the Modbus broadcast address, which no module answers; "
                  "use 1..%1.")
            .arg(QLocale().toString(kMaxUnit));
    return {};
}

void SerialPage::retranslate()
{
    m_portLabel->setText(tr("&Port:"));
    m_portLabel->setBuddy(m_port);
    m_line->retranslate();
    m_addressLabel->setText(tr("Module &address:"));
    m_addressLabel->setBuddy(m_address);
    m_address->setToolTip(tr("Modbus unit: the module's address on an RS485 line (E22, DIP "
                             "switches); 1 on a point-to-point line"));
    m_productLabel->setText(tr("Pro&duct:"));
    m_productLabel->setBuddy(m_product);
}

} // namespace vt::ui
