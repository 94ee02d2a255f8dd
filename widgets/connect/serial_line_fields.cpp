#include "serial_line_fields.h"

#include "model/text_language.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>

namespace vt::ui {

namespace {

// Rates a USB-RS485 adapter offers; 19200 is the HCS default (ARCHITECTURE.md), 1200 HART.
constexpr int kCommonRates[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200};

// Baud rates are identifiers more than quantities: no group separator ("19200", not "19.200").
QLocale rateLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

} // namespace

SerialLineFields::SerialLineFields(const QString &name, QFormLayout *form, QWidget *owner)
    : QObject(owner)
{
    m_baud = new QComboBox(owner);
    m_baud->setObjectName(name + QStringLiteral("Baud"));
    m_baud->setEditable(true);
    m_baud->setInsertPolicy(QComboBox::NoInsert);
    for (int rate : kCommonRates)
        m_baud->addItem(rateLocale().toString(rate), rate);
    m_dataBits = new QComboBox(owner);
    m_dataBits->setObjectName(name + QStringLiteral("DataBits"));
    for (int bits = 8; bits >= 5; --bits)
        m_dataBits->addItem(rateLocale().toString(bits), bits);
    m_parity = new QComboBox(owner);
    m_parity->setObjectName(name + QStringLiteral("Parity"));
    for (link::Parity p : {link::Parity::None, link::Parity::Even, link::Parity::Odd})
        m_parity->addItem(QString(), static_cast<int>(p));
    m_stopBits = new QComboBox(owner);
    m_stopBits->setObjectName(name + QStringLiteral("StopBits"));
    m_stopBits->addItem(rateLocale().toString(1), 1);
    m_stopBits->addItem(rateLocale().toString(2), 2);

    m_baudLabel = new QLabel(owner);
    m_dataBitsLabel = new QLabel(owner);
    m_parityLabel = new QLabel(owner);
    m_stopBitsLabel = new QLabel(owner);
    form->addRow(m_baudLabel, m_baud);
    form->addRow(m_dataBitsLabel, m_dataBits);
    form->addRow(m_parityLabel, m_parity);
    form->addRow(m_stopBitsLabel, m_stopBits);

    connect(m_baud, &QComboBox::editTextChanged, this, &SerialLineFields::changed);
    for (QComboBox *box : {m_dataBits, m_parity, m_stopBits})
        connect(box, &QComboBox::currentIndexChanged, this, &SerialLineFields::changed);
    setSettings(link::SerialSettings::hcsDefault(QString()));
    retranslate();
}

model::NumberParse SerialLineFields::parsedBaudRate() const
{
    model::NumberRules rules;
    rules.minimum = 1;
    rules.maximum = 4000000;
    return model::parseNumber(m_baud->currentText(), model::textLanguage(), rules);
}

int SerialLineFields::baudRate() const
{
    const model::NumberParse rate = parsedBaudRate();
    return rate.ok() ? static_cast<int>(*rate.value) : 0;
}

link::SerialSettings SerialLineFields::settings(const QString &portName) const
{
    link::SerialSettings s;
    s.portName = portName;
    s.baudRate = baudRate();
    s.dataBits = m_dataBits->currentData().toInt();
    s.parity = static_cast<link::Parity>(m_parity->currentData().toInt());
    s.stopBits = m_stopBits->currentData().toInt() == 2 ? link::StopBits::Two : link::StopBits::One;
    return s;
}

void SerialLineFields::setSettings(const link::SerialSettings &settings)
{
    const int rate = m_baud->findData(settings.baudRate);
    if (rate >= 0)
        m_baud->setCurrentIndex(rate);
    else
        m_baud->setEditText(rateLocale().toString(settings.baudRate));
    m_dataBits->setCurrentIndex(std::max(0, m_dataBits->findData(settings.dataBits)));
    m_parity->setCurrentIndex(std::max(0, m_parity->findData(static_cast<int>(settings.parity))));
    m_stopBits->setCurrentIndex(
        std::max(0, m_stopBits->findData(static_cast<int>(settings.stopBits))));
}

QString SerialLineFields::problem() const
{
    if (const model::NumberParse rate = parsedBaudRate(); !rate.ok())
        return tr("Baud rate: %1").arg(rate.refusal);
    return {};
}

void SerialLineFields::retranslate()
{
    m_baudLabel->setText(tr("&Baud rate:"));
    m_baudLabel->setBuddy(m_baud);
    m_dataBitsLabel->setText(tr("&Data bits:"));
    m_dataBitsLabel->setBuddy(m_dataBits);
    m_parityLabel->setText(tr("Pa&rity:"));
    m_parityLabel->setBuddy(m_parity);
    m_stopBitsLabel->setText(tr("&Stop bits:"));
    m_stopBitsLabel->setBuddy(m_stopBits);
    for (int i = 0; i < m_parity->count(); ++i) {
        switch (static_cast<link::Parity>(m_parity->itemData(i).toInt())) {
        case link::Parity::None: m_parity->setItemText(i, tr("None (N)")); break;
        case link::Parity::Even: m_parity->setItemText(i, tr("Even (E)")); break;
        case link::Parity::Odd: m_parity->setItemText(i, tr("Odd (O)")); break;
        }
    }
}

} // namespace vt::ui
