#include "can_page.h"

#include "widgets/connect/hcs_product_box.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace vt::ui {

namespace {

// CANopen node ids are 1..127 (0 addresses every node in NMT and is no SDO server).
constexpr int kMinNode = 1;
constexpr int kMaxNode = 127;

} // namespace

CanPage::CanPage(QWidget *parent) : ConnectPage(parent)
{
    setObjectName(QStringLiteral("canPage"));
    auto *form = new QFormLayout(this);
    m_interface = new QLineEdit(QStringLiteral("can0"), this);
    m_interface->setObjectName(QStringLiteral("canInterface"));
    m_interfaceLabel = new QLabel(this);
    form->addRow(m_interfaceLabel, m_interface);
    m_node = new WholeNumberBox(this);
    m_node->setObjectName(QStringLiteral("canNode"));
    // Wider than valid so that problem() can say why 0 or 128 does not work.
    m_node->setRange(0, 255);
    m_node->setValue(kMinNode);
    m_nodeLabel = new QLabel(this);
    form->addRow(m_nodeLabel, m_node);
    m_device = new QComboBox(this);
    m_device->setObjectName(QStringLiteral("canDevice"));
    m_device->addItem(QString(), false);
    m_device->addItem(QString(), true);
    m_deviceLabel = new QLabel(this);
    form->addRow(m_deviceLabel, m_device);
    m_product = new HcsProductBox(this);
    m_product->setObjectName(QStringLiteral("canProduct"));
    m_productLabel = new QLabel(this);
    form->addRow(m_productLabel, m_product);

    connect(m_interface, &QLineEdit::textChanged, this, &ConnectPage::changed);
    connect(m_node, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    connect(m_device, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabled();
        emit changed();
    });
    connect(m_product, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    updateEnabled();
    retranslate();
}

QString CanPage::title() const
{
    return tr("CAN (CANopen)");
}

void CanPage::load(const model::ConnectionSpec &spec)
{
    if (!spec.canInterface.isEmpty())
        m_interface->setText(spec.canInterface);
    m_node->setValue(spec.canNode);
    m_device->setCurrentIndex(spec.canDsp408 ? 1 : 0);
    m_product->setProduct(spec.product);
}

model::ConnectionSpec CanPage::spec() const
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Can;
    spec.canInterface = m_interface->text().trimmed();
    spec.canNode = m_node->value();
    spec.canDsp408 = m_device->currentData().toBool();
    spec.product = spec.canDsp408 ? dev::HcsProduct::Unknown : m_product->product();
    return spec;
}

QString CanPage::problem() const
{
    const QString name = m_interface->text().trimmed();
    if (name.isEmpty())
        return tr("Type the CAN interface (can0, vcan0 …).");
    if (name.contains(QLatin1Char(' ')) || name.contains(QLatin1Char('/')))
        return tr("\"%1\" is not a network interface name.").arg(name);
    const int node = m_node->value();
    if (node < kMinNode || node > kMaxNode)
        return tr("CANopen node id %1 is outside %2..%3.")
            .arg(QLocale().toString(node), QLocale().toString(kMinNode),
                 QLocale().toString(kMaxNode));
    return {};
}

void CanPage::updateEnabled()
{
    // The HCS product only picks HCS exception tables and versions; an ED1 identifies itself.
    const bool hcs = !m_device->currentData().toBool();
    m_product->setEnabled(hcs);
    m_productLabel->setEnabled(hcs);
}

void CanPage::retranslate()
{
    m_interfaceLabel->setText(tr("&Interface:"));
    m_interfaceLabel->setBuddy(m_interface);
    m_nodeLabel->setText(tr("&Node id:"));
    m_nodeLabel->setBuddy(m_node);
    m_deviceLabel->setText(tr("&Device:"));
    m_deviceLabel->setBuddy(m_device);
    m_device->setItemText(0, tr("HCS module (objects 0x2000 + ID)"));
    m_device->setItemText(1, tr("Wandfluh ED1 (CiA 408)"));
    m_productLabel->setText(tr("Pro&duct:"));
    m_productLabel->setBuddy(m_product);
}

} // namespace vt::ui
