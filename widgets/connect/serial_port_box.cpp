#include "serial_port_box.h"

#include "transports/serial_ports.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QToolButton>

namespace vt::ui {

SerialPortBox::SerialPortBox(const QString &name, QWidget *parent) : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_combo = new QComboBox(this);
    m_combo->setObjectName(name + QStringLiteral("Port"));
    m_combo->setEditable(true);
    m_combo->setInsertPolicy(QComboBox::NoInsert);
    m_combo->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    layout->addWidget(m_combo);
    m_refresh = new QToolButton(this);
    m_refresh->setObjectName(name + QStringLiteral("Refresh"));
    layout->addWidget(m_refresh);
    connect(m_refresh, &QToolButton::clicked, this, &SerialPortBox::refresh);
    connect(m_combo, &QComboBox::editTextChanged, this, &SerialPortBox::changed);
    refresh();
    retranslate();
}

QString SerialPortBox::portName() const
{
    // An enumerated entry shows "path — description"; the path is its data.
    const QString text = m_combo->currentText().trimmed();
    const int index = m_combo->findText(text);
    if (index >= 0 && !m_combo->itemData(index).toString().isEmpty())
        return m_combo->itemData(index).toString();
    return text;
}

void SerialPortBox::setPortName(const QString &name)
{
    const int index = m_combo->findData(name);
    if (index >= 0)
        m_combo->setCurrentIndex(index);
    else
        m_combo->setEditText(name);
}

void SerialPortBox::refresh()
{
    const QString current = portName();
    const QSignalBlocker block(m_combo);
    m_combo->clear();
    for (const link::SerialPortInfo &port : link::availableSerialPorts())
        m_combo->addItem(port.displayText(), port.name);
    // Nothing chosen yet: the first enumerated port; otherwise what was there, typed or picked.
    if (current.isEmpty() && m_combo->count() > 0)
        m_combo->setCurrentIndex(0);
    else
        setPortName(current);
    emit changed();
}

void SerialPortBox::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SerialPortBox::retranslate()
{
    m_refresh->setText(tr("Refresh"));
    m_refresh->setToolTip(tr("List the serial ports again"));
    m_combo->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0"));
}

} // namespace vt::ui
