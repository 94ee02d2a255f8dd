#include "sim_page.h"

#include "dict/dictionary.h"
#include "widgets/connect/language_text.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>

namespace vt::ui {

namespace {

// A fold holds up to 1 + 7 OPAT modules (OPAT manual §1.4); the DMA-2 node is offered to the same
// size, enough for every fold the node image carries (CMD 15: up to 5 DMA modules).
constexpr int kMaxModules = 8;

// The protocol choice's item data: the link protocol's key, empty for the family's default.
std::optional<dev::LinkProtocol> protocolOfData(const QVariant &data)
{
    return dev::fromKey<dev::LinkProtocol>(data.toString().toStdString());
}

QString dataOfProtocol(std::optional<dev::LinkProtocol> protocol)
{
    return protocol ? QString::fromLatin1(dev::key(*protocol)) : QString();
}

bool simulated(const dev::Dictionary &dict)
{
    return !dict.abstract && model::servedOverSimLink(dict.protocol);
}

} // namespace

SimPage::SimPage(const dev::DictionarySet &dictionaries, QWidget *parent)
    : ConnectPage(parent), m_dictionaries(dictionaries)
{
    setObjectName(QStringLiteral("simPage"));
    auto *form = new QFormLayout(this);
    m_family = new QComboBox(this);
    m_family->setObjectName(QStringLiteral("simFamily"));
    for (const std::string &family : m_dictionaries.families()) {
        const dev::Dictionary *dict = m_dictionaries.find(family);
        if (dict && simulated(*dict))
            m_family->addItem(QString(), QString::fromStdString(family));
    }
    m_familyLabel = new QLabel(this);
    form->addRow(m_familyLabel, m_family);
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("simMode"));
    m_modeLabel = new QLabel(this);
    form->addRow(m_modeLabel, m_mode);
    m_modules = new WholeNumberBox(this);
    m_modules->setObjectName(QStringLiteral("simModules"));
    m_modules->setRange(1, kMaxModules);
    m_modulesLabel = new QLabel(this);
    form->addRow(m_modulesLabel, m_modules);
    m_protocol = new QComboBox(this);
    m_protocol->setObjectName(QStringLiteral("simProtocol"));
    m_protocolLabel = new QLabel(this);
    form->addRow(m_protocolLabel, m_protocol);

    connect(m_family, &QComboBox::currentIndexChanged, this, [this] {
        fillForFamily();
        emit changed();
    });
    connect(m_mode, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    connect(m_modules, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ConnectPage::changed);
    fillForFamily();
    retranslate();
}

std::vector<std::string> SimPage::families() const
{
    std::vector<std::string> out;
    for (int i = 0; i < m_family->count(); ++i)
        out.push_back(m_family->itemData(i).toString().toStdString());
    return out;
}

const dev::Dictionary *SimPage::dictionary() const
{
    return m_dictionaries.find(m_family->currentData().toString().toStdString());
}

void SimPage::fillForFamily()
{
    const dev::Dictionary *dict = dictionary();
    const bool hcs = dict && dict->protocol == dev::DeviceProtocol::Hcs;
    {
        const QSignalBlocker blockMode(m_mode);
        const QSignalBlocker blockProtocol(m_protocol);
        m_mode->clear();
        m_protocol->clear();
        // HCS modes are E00 numbers the simulated modules start in; the SD7 simulator has no
        // mode to choose at start-up.
        if (hcs) {
            for (const std::string &mode : dict->modes)
                m_mode->addItem(QString(), QString::fromStdString(mode).toInt());
            m_protocol->addItem(QString(), dataOfProtocol(std::nullopt));
            for (dev::LinkProtocol p : {dev::LinkProtocol::ModbusRtu, dev::LinkProtocol::ModbusTcp,
                                        dev::LinkProtocol::NodeImage})
                m_protocol->addItem(QString(), dataOfProtocol(p));
        } else if (dict && dict->protocol == dev::DeviceProtocol::Dsp408) {
            for (dev::LinkProtocol p :
                 {dev::LinkProtocol::Dsp408Image, dev::LinkProtocol::Dsp408Gateway})
                m_protocol->addItem(QString(), dataOfProtocol(p));
        } else {
            m_protocol->addItem(QString(), dataOfProtocol(dev::LinkProtocol::Hart));
        }
    }
    m_mode->setEnabled(hcs);
    m_modeLabel->setEnabled(hcs);
    m_modules->setEnabled(hcs);
    m_modulesLabel->setEnabled(hcs);
    if (!hcs)
        m_modules->setValue(1);
    m_protocol->setEnabled(m_protocol->count() > 1);
    retranslateChoices();
}

QString SimPage::title() const
{
    return tr("Simulator");
}

void SimPage::load(const model::ConnectionSpec &spec)
{
    const int family = m_family->findData(QString::fromStdString(spec.sim.family));
    if (family >= 0)
        m_family->setCurrentIndex(family);
    if (m_modules->isEnabled())
        m_modules->setValue(static_cast<int>(spec.sim.modules));
    const int mode = m_mode->findData(spec.sim.mode);
    m_mode->setCurrentIndex(mode >= 0 ? mode : 0);
    const int protocol = m_protocol->findData(dataOfProtocol(spec.sim.protocol));
    m_protocol->setCurrentIndex(protocol >= 0 ? protocol : 0);
}

model::ConnectionSpec SimPage::spec() const
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = m_family->currentData().toString().toStdString();
    spec.sim.modules = static_cast<std::size_t>(m_modules->value());
    spec.sim.mode = m_mode->count() > 0 ? m_mode->currentData().toInt() : 0;
    spec.sim.protocol = protocolOfData(m_protocol->currentData());
    return spec;
}

QString SimPage::problem() const
{
    const dev::Dictionary *dict = dictionary();
    if (!dict)
        return tr("No device family can be simulated: the dictionaries did not load.");
    // On a serial line unit 0 is the broadcast address, and that is where the OPAT master sits
    // (sim_endpoint.cpp): a node with slaves needs its gateway's Modbus TCP or the node image.
    if (dict->family == "opat" && m_modules->value() > 1 &&
        protocolOfData(m_protocol->currentData()) == dev::LinkProtocol::ModbusRtu)
        return tr("Over Modbus RTU the OPAT master (address 0) is the broadcast address and cannot "
                  "answer; choose Modbus TCP or the node image for a node with slaves.");
    return {};
}

void SimPage::retranslate()
{
    m_familyLabel->setText(tr("&Family:"));
    m_familyLabel->setBuddy(m_family);
    m_modeLabel->setText(tr("&Mode:"));
    m_modeLabel->setBuddy(m_mode);
    m_modulesLabel->setText(tr("M&odules:"));
    m_modulesLabel->setBuddy(m_modules);
    m_modules->setToolTip(tr("Modules of the node: an OPAT master and its CAN slaves, or DMA-2 "
                             "modules with addresses 1, 2, 3 …"));
    m_protocolLabel->setText(tr("&Protocol:"));
    m_protocolLabel->setBuddy(m_protocol);
    for (int i = 0; i < m_family->count(); ++i) {
        const std::string id = m_family->itemData(i).toString().toStdString();
        if (const dev::Dictionary *dict = m_dictionaries.find(id))
            m_family->setItemText(i, familyText(*dict));
    }
    retranslateChoices();
}

void SimPage::retranslateChoices()
{
    if (const dev::Dictionary *dict = dictionary())
        for (int i = 0; i < m_mode->count(); ++i)
            m_mode->setItemText(i, modeText(*dict, std::to_string(m_mode->itemData(i).toInt())));
    if (m_mode->count() == 0)
        m_mode->setPlaceholderText(tr("not chosen at start-up"));
    for (int i = 0; i < m_protocol->count(); ++i) {
        const auto protocol = protocolOfData(m_protocol->itemData(i));
        QString text = tr("Automatic (Modbus RTU for one module, Modbus TCP for a node)");
        if (protocol) {
            switch (*protocol) {
            case dev::LinkProtocol::ModbusRtu: text = tr("Modbus RTU"); break;
            case dev::LinkProtocol::ModbusTcp: text = tr("Modbus TCP"); break;
            case dev::LinkProtocol::NodeImage:
                text = tr("Node image (cyclic telegrams, CMD 3/6/15)");
                break;
            case dev::LinkProtocol::Hart: text = tr("HART"); break;
            case dev::LinkProtocol::Canopen: text = QString::fromLatin1(dev::key(*protocol)); break;
            case dev::LinkProtocol::Dsp408Image:
                text = tr("PROFIBUS image (PKW + PZD, cyclic)");
                break;
            case dev::LinkProtocol::Dsp408Gateway:
                text = tr("PROFIBUS gateway (Modbus TCP registers)");
                break;
            }
        }
        m_protocol->setItemText(i, text);
    }
}

} // namespace vt::ui
