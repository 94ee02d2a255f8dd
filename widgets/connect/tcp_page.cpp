#include "tcp_page.h"

#include "widgets/connect/dsp408_fields.h"
#include "widgets/connect/hcs_product_box.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace vt::ui {

namespace {

constexpr int kModbusTcpPort = 502;
// Over TCP there is no broadcast unit: 0 reaches the OPAT master (ARCHITECTURE.md).
constexpr int kMaxUnit = 255;

} // namespace

TcpPage::TcpPage(QWidget *parent) : ConnectPage(parent)
{
    setObjectName(QStringLiteral("tcpPage"));
    auto *form = new QFormLayout(this);
    m_host = new QLineEdit(this);
    m_host->setObjectName(QStringLiteral("tcpHost"));
    m_hostLabel = new QLabel(this);
    form->addRow(m_hostLabel, m_host);
    m_port = new WholeNumberBox(this);
    m_port->setObjectName(QStringLiteral("tcpPort"));
    m_port->setRange(0, 65535);
    m_port->setValue(kModbusTcpPort);
    m_portLabel = new QLabel(this);
    form->addRow(m_portLabel, m_port);
    m_protocol = new QComboBox(this);
    m_protocol->setObjectName(QStringLiteral("tcpProtocol"));
    m_protocol->addItem(QString(), static_cast<int>(dev::LinkProtocol::ModbusTcp));
    m_protocol->addItem(QString(), static_cast<int>(dev::LinkProtocol::NodeImage));
    m_protocol->addItem(QString(), static_cast<int>(dev::LinkProtocol::Dsp408Gateway));
    m_protocol->addItem(QString(), static_cast<int>(dev::LinkProtocol::Dsp408Image));
    m_protocolLabel = new QLabel(this);
    form->addRow(m_protocolLabel, m_protocol);
    m_address = new WholeNumberBox(this);
    m_address->setObjectName(QStringLiteral("tcpAddress"));
    m_address->setRange(0, kMaxUnit);
    m_address->setValue(1);
    m_addressLabel = new QLabel(this);
    form->addRow(m_addressLabel, m_address);
    m_product = new HcsProductBox(this);
    m_product->setObjectName(QStringLiteral("tcpProduct"));
    m_productLabel = new QLabel(this);
    form->addRow(m_productLabel, m_product);
    m_dsp408 = new Dsp408Fields(this);
    m_dsp408->setObjectName(QStringLiteral("tcpDsp408"));
    form->addRow(m_dsp408);

    connect(m_host, &QLineEdit::textChanged, this, &ConnectPage::changed);
    connect(m_port, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    connect(m_address, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    connect(m_product, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    connect(m_dsp408, &Dsp408Fields::changed, this, &ConnectPage::changed);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &TcpPage::fitProtocol);
    retranslate();
    fitProtocol();
}

void TcpPage::fitProtocol()
{
    const auto protocol = static_cast<dev::LinkProtocol>(m_protocol->currentData().toInt());
    const bool ed1 = dev::isDsp408Link(protocol);
    m_dsp408->setVisible(ed1);
    m_dsp408->setGateway(protocol == dev::LinkProtocol::Dsp408Gateway);
    m_product->setVisible(!ed1);
    m_productLabel->setVisible(!ed1);
    // The raw image has one slave and no address on the wire.
    m_address->setVisible(protocol != dev::LinkProtocol::Dsp408Image);
    m_addressLabel->setVisible(protocol != dev::LinkProtocol::Dsp408Image);
}

QString TcpPage::title() const
{
    return tr("TCP");
}

void TcpPage::load(const model::ConnectionSpec &spec)
{
    m_host->setText(spec.host);
    m_port->setValue(spec.port);
    m_protocol->setCurrentIndex(
        std::max(0, m_protocol->findData(static_cast<int>(spec.tcpProtocol))));
    m_address->setValue(spec.unit.value_or(1));
    m_product->setProduct(spec.product);
    m_dsp408->load(spec.dsp408);
}

model::ConnectionSpec TcpPage::spec() const
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Tcp;
    spec.host = m_host->text().trimmed();
    spec.port = static_cast<quint16>(m_port->value());
    spec.tcpProtocol = static_cast<dev::LinkProtocol>(m_protocol->currentData().toInt());
    spec.unit = m_address->value();
    spec.product = m_product->product();
    if (dev::isDsp408Link(spec.tcpProtocol)) {
        spec.product = dev::HcsProduct::Unknown;
        spec.dsp408 = m_dsp408->options();
        if (spec.tcpProtocol == dev::LinkProtocol::Dsp408Image)
            spec.unit.reset();
    }
    return spec;
}

QString TcpPage::problem() const
{
    const QString host = m_host->text().trimmed();
    if (host.isEmpty())
        return tr("Type the host name or IP address of the gateway.");
    if (host.contains(QLatin1Char(' ')))
        return tr("A host name has no spaces: \"%1\".").arg(host);
    if (m_port->value() == 0)
        return tr("Port 0 cannot be connected to; Modbus TCP uses %1.")
            .arg(QLocale().toString(kModbusTcpPort));
    return {};
}

void TcpPage::retranslate()
{
    m_hostLabel->setText(tr("&Host:"));
    m_hostLabel->setBuddy(m_host);
    m_host->setPlaceholderText(tr("192.168.0.10 or gateway.local"));
    m_portLabel->setText(tr("P&ort:"));
    m_portLabel->setBuddy(m_port);
    m_protocolLabel->setText(tr("P&rotocol:"));
    m_protocolLabel->setBuddy(m_protocol);
    m_protocol->setItemText(0, tr("Modbus TCP"));
    m_protocol->setItemText(1, tr("Node image (cyclic telegrams, CMD 3/6/15)"));
    m_protocol->setItemText(2, tr("Wandfluh ED1: PROFIBUS gateway (Modbus TCP registers)"));
    m_protocol->setItemText(3, tr("Wandfluh ED1: PROFIBUS image (PKW + PZD, cyclic)"));
    m_addressLabel->setText(tr("Module &address:"));
    m_addressLabel->setBuddy(m_address);
    m_address->setToolTip(tr("Modbus unit / SADR of the module; 0 is the OPAT master; for the "
                             "ED1's gateway its Modbus unit"));
    m_productLabel->setText(tr("Pro&duct:"));
    m_productLabel->setBuddy(m_product);
}

} // namespace vt::ui
