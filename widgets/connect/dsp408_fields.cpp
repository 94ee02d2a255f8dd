#include "dsp408_fields.h"

#include "widgets/number_box.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>

namespace vt::ui {

namespace {

// The image's 7 registers must fit below 65536.
constexpr int kMaxFirstRegister = 0xFFFF - 7;

} // namespace

Dsp408Fields::Dsp408Fields(QWidget *parent) : QWidget(parent)
{
    m_form = new QFormLayout(this);
    m_form->setContentsMargins(0, 0, 0, 0);
    auto spin = [this](const char *name) {
        auto *box = new WholeNumberBox(this);
        box->setObjectName(QLatin1String(name));
        box->setRange(0, kMaxFirstRegister);
        connect(box, &QSpinBox::valueChanged, this, &Dsp408Fields::changed);
        return box;
    };
    auto combo = [this](const char *name, int items) {
        auto *box = new QComboBox(this);
        box->setObjectName(QLatin1String(name));
        for (int i = 0; i < items; ++i)
            box->addItem(QString(), i);
        connect(box, &QComboBox::currentIndexChanged, this, &Dsp408Fields::changed);
        return box;
    };
    m_output = spin("dsp408OutputRegister");
    m_input = spin("dsp408InputRegister");
    m_function = combo("dsp408InputFunction", 2);
    m_bytes = combo("dsp408RegisterBytes", 2);
    m_words = combo("dsp408PzdWords", 2);
    m_ind = combo("dsp408IndByte", 2);
    m_outputLabel = new QLabel(this);
    m_inputLabel = new QLabel(this);
    m_functionLabel = new QLabel(this);
    m_bytesLabel = new QLabel(this);
    m_wordsLabel = new QLabel(this);
    m_indLabel = new QLabel(this);
    m_form->addRow(m_outputLabel, m_output);
    m_form->addRow(m_inputLabel, m_input);
    m_form->addRow(m_functionLabel, m_function);
    m_form->addRow(m_bytesLabel, m_bytes);
    m_form->addRow(m_wordsLabel, m_words);
    m_form->addRow(m_indLabel, m_ind);
    load({});
    retranslate();
}

void Dsp408Fields::load(const dev::access::Dsp408LinkOptions &o)
{
    m_output->setValue(o.gateway.outputRegister);
    m_input->setValue(o.gateway.inputRegister);
    m_function->setCurrentIndex(
        o.gateway.inputFunction == dev::dsp408::InputFunction::InputRegisters ? 1 : 0);
    m_bytes->setCurrentIndex(o.gateway.byteOrder == dev::dsp408::RegisterByteOrder::FirstByteLow);
    m_words->setCurrentIndex(o.layout.pzdWordOrder == dev::dsp408::WordOrder::LowWordFirst);
    m_ind->setCurrentIndex(o.layout.indPosition == dev::dsp408::IndPosition::Byte3);
}

dev::access::Dsp408LinkOptions Dsp408Fields::options() const
{
    dev::access::Dsp408LinkOptions o;
    o.gateway.outputRegister = static_cast<std::uint16_t>(m_output->value());
    o.gateway.inputRegister = static_cast<std::uint16_t>(m_input->value());
    o.gateway.inputFunction = m_function->currentIndex() == 1
                                  ? dev::dsp408::InputFunction::InputRegisters
                                  : dev::dsp408::InputFunction::HoldingRegisters;
    o.gateway.byteOrder = m_bytes->currentIndex() == 1
                              ? dev::dsp408::RegisterByteOrder::FirstByteLow
                              : dev::dsp408::RegisterByteOrder::FirstByteHigh;
    o.layout.pzdWordOrder = m_words->currentIndex() == 1 ? dev::dsp408::WordOrder::LowWordFirst
                                                         : dev::dsp408::WordOrder::HighWordFirst;
    o.layout.indPosition = m_ind->currentIndex() == 1 ? dev::dsp408::IndPosition::Byte3
                                                      : dev::dsp408::IndPosition::Byte2;
    return o;
}

void Dsp408Fields::setGateway(bool gateway)
{
    for (QWidget *w :
         {static_cast<QWidget *>(m_output), static_cast<QWidget *>(m_input),
          static_cast<QWidget *>(m_function), static_cast<QWidget *>(m_bytes),
          static_cast<QWidget *>(m_outputLabel), static_cast<QWidget *>(m_inputLabel),
          static_cast<QWidget *>(m_functionLabel), static_cast<QWidget *>(m_bytesLabel)})
        w->setVisible(gateway);
}

void Dsp408Fields::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void Dsp408Fields::retranslate()
{
    m_outputLabel->setText(tr("O&utput image at register:"));
    m_outputLabel->setBuddy(m_output);
    m_output->setToolTip(tr("First register of the ED1's output image (PKW request and PZD, 7 "
                            "registers) in the gateway's map; written with FC 16."));
    m_inputLabel->setText(tr("I&nput image at register:"));
    m_inputLabel->setBuddy(m_input);
    m_input->setToolTip(tr("First register of the ED1's input image (PKW response and PZD, 7 "
                           "registers) in the gateway's map."));
    m_functionLabel->setText(tr("Input image read &with:"));
    m_functionLabel->setBuddy(m_function);
    m_function->setItemText(0, tr("FC 3 (holding registers)"));
    m_function->setItemText(1, tr("FC 4 (input registers)"));
    m_bytesLabel->setText(tr("Image &bytes in a register:"));
    m_bytesLabel->setBuddy(m_bytes);
    m_bytes->setItemText(0, tr("First byte high (as Modbus)"));
    m_bytes->setItemText(1, tr("First byte low (swapped)"));
    m_wordsLabel->setText(tr("32-bit PZD &values:"));
    m_wordsLabel->setBuddy(m_words);
    m_words->setItemText(0, tr("High word first (the manual's examples)"));
    m_words->setItemText(1, tr("Low word first"));
    m_indLabel->setText(tr("PKW &IND in:"));
    m_indLabel->setBuddy(m_ind);
    m_ind->setItemText(0, tr("Byte 2 (the manual's example)"));
    m_ind->setItemText(1, tr("Byte 3"));
}

} // namespace vt::ui
