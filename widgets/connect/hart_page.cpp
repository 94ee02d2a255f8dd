#include "hart_page.h"

#include "widgets/connect/serial_port_box.h"
#include "widgets/number_box.h"

#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>

namespace vt::ui {

namespace {

// The poll addresses a scan tries (model/session/connection.cpp); 0 is point-to-point.
constexpr int kMaxPollAddress = 15;

} // namespace

HartPage::HartPage(QWidget *parent) : ConnectPage(parent)
{
    setObjectName(QStringLiteral("hartPage"));
    auto *form = new QFormLayout(this);
    m_port = new SerialPortBox(QStringLiteral("hart"), this);
    m_portLabel = new QLabel(this);
    form->addRow(m_portLabel, m_port);
    m_line = new QLabel(this);
    m_line->setObjectName(QStringLiteral("hartLine"));
    m_lineLabel = new QLabel(this);
    form->addRow(m_lineLabel, m_line);
    m_poll = new WholeNumberBox(this);
    m_poll->setObjectName(QStringLiteral("hartPollAddress"));
    m_poll->setRange(0, kMaxPollAddress);
    m_pollLabel = new QLabel(this);
    form->addRow(m_pollLabel, m_poll);

    connect(m_port, &SerialPortBox::changed, this, &ConnectPage::changed);
    connect(m_poll, &QSpinBox::valueChanged, this, &ConnectPage::changed);
    retranslate();
}

QString HartPage::title() const
{
    return tr("HART");
}

void HartPage::load(const model::ConnectionSpec &spec)
{
    m_port->setPortName(spec.serial.portName);
    m_poll->setValue(spec.unit.value_or(0));
}

model::ConnectionSpec HartPage::spec() const
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Hart;
    spec.serial = link::SerialSettings::hart(m_port->portName());
    spec.unit = m_poll->value();
    return spec;
}

QString HartPage::problem() const
{
    if (m_port->portName().isEmpty())
        return tr("Choose the HART modem's serial port or type its path.");
    return {};
}

void HartPage::retranslate()
{
    m_portLabel->setText(tr("&Port:"));
    m_portLabel->setBuddy(m_port);
    m_lineLabel->setText(tr("Line:"));
    const link::SerialSettings line = link::SerialSettings::hart(QString());
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    m_line->setText(
        tr("%1 baud %2 (fixed by HART)").arg(locale.toString(line.baudRate), line.formatText()));
    m_pollLabel->setText(tr("P&oll address:"));
    m_pollLabel->setBuddy(m_poll);
    m_poll->setToolTip(tr("0 for a single device on the loop"));
}

} // namespace vt::ui
