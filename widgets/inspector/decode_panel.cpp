#include "decode_panel.h"

#include "canopen/can_frame.h"
#include "frame_detail.h"
#include "inspect/auto_detect.h"
#include "inspect/hex_input.h"
#include "inspect/logged_frame.h"
#include "model/text_language.h"
#include "transports/byte_span.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QVBoxLayout>
#include <algorithm>

namespace vt::ui {
namespace {

using vt::dev::Direction;
using vt::dev::FrameFormat;

constexpr int kAuto = -1;

QString protocolKey(FrameFormat p)
{
    return QString::fromLatin1(vt::dev::key(p));
}

} // namespace

DecodePanel::DecodePanel(QWidget *parent)
    : QWidget(parent), m_input(new QPlainTextEdit(this)), m_protocol(new QComboBox(this)),
      m_family(new QComboBox(this)), m_direction(new QComboBox(this)),
      m_protocolLabel(new QLabel(this)), m_familyLabel(new QLabel(this)),
      m_directionLabel(new QLabel(this)), m_status(new QLabel(this)),
      m_detail(new FrameDetail(this))
{
    m_input->setTabChangesFocus(true);
    m_input->setMaximumBlockCount(2000);
    m_input->setFixedHeight(m_input->fontMetrics().height() * 4 + 12);
    m_protocol->addItem(QString(), kAuto);
    for (FrameFormat p : vt::dev::kFrameFormats)
        m_protocol->addItem(protocolKey(p), static_cast<int>(p));
    m_family->addItem(QStringLiteral("DMA"), static_cast<int>(vt::dev::hcs::Family::Dma));
    m_family->addItem(QStringLiteral("OPAT"), static_cast<int>(vt::dev::hcs::Family::Opat));
    m_direction->addItem(QString(), static_cast<int>(Direction::Request));
    m_direction->addItem(QString(), static_cast<int>(Direction::Response));
    m_status->setWordWrap(true);

    auto *options = new QHBoxLayout;
    options->addWidget(m_protocolLabel);
    options->addWidget(m_protocol);
    options->addWidget(m_familyLabel);
    options->addWidget(m_family);
    options->addWidget(m_directionLabel);
    options->addWidget(m_direction);
    options->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_input);
    layout->addLayout(options);
    layout->addWidget(m_status);
    layout->addWidget(m_detail, 1);

    connect(m_input, &QPlainTextEdit::textChanged, this, &DecodePanel::decode);
    for (QComboBox *box : {m_protocol, m_family, m_direction})
        connect(box, &QComboBox::currentIndexChanged, this, &DecodePanel::decode);
    retranslate();
}

void DecodePanel::setDictionary(const vt::dev::Dictionary *dictionary)
{
    m_dictionary = dictionary;
    decode();
}

void DecodePanel::setFamily(vt::dev::hcs::Family family)
{
    m_family->setCurrentIndex(m_family->findData(static_cast<int>(family)));
}

void DecodePanel::setText(const QString &text)
{
    m_input->setPlainText(text);
}

QString DecodePanel::text() const
{
    return m_input->toPlainText();
}

void DecodePanel::setProtocol(std::optional<FrameFormat> protocol)
{
    m_protocol->setCurrentIndex(
        m_protocol->findData(protocol ? static_cast<int>(*protocol) : kAuto));
}

void DecodePanel::setDirection(Direction direction)
{
    m_direction->setCurrentIndex(m_direction->findData(static_cast<int>(direction)));
}

QString DecodePanel::statusText() const
{
    return m_status->text();
}

void DecodePanel::setStatus(const QString &text, bool problem)
{
    m_status->setStyleSheet(problem ? QStringLiteral("color: #c81e1e;") : QString());
    m_status->setText(text);
}

void DecodePanel::decode()
{
    m_decoded.reset();
    m_description = {};
    const QString text = m_input->toPlainText();
    if (text.trimmed().isEmpty()) {
        m_detail->clear();
        setStatus(tr("Paste or type a frame as hex (\"23 00 06\", \"0x23,0x00\", \"230006\") or a "
                     "CAN frame as \"605#40416000\"."),
                  false);
        return;
    }
    const std::string utf8 = text.toStdString();
    const auto input = vt::dev::inspect::parseHexInput(utf8);
    if (!input) {
        m_detail->clear();
        if (utf8.size() > vt::dev::inspect::kMaxInputChars)
            setStatus(tr("Too long: at most %1 characters.")
                          .arg(QLocale().toString(
                              static_cast<qulonglong>(vt::dev::inspect::kMaxInputChars))),
                      true);
        else
            setStatus(
                tr("Not hex at character %1.")
                    .arg(QLocale().toString(static_cast<qulonglong>(input.error().position + 1))),
                true);
        return;
    }
    const QByteArray bytes = vt::link::toByteArray(input->bytes);

    vt::dev::AnyOptions options;
    options.family = static_cast<vt::dev::hcs::Family>(m_family->currentData().toInt());
    options.direction = static_cast<Direction>(m_direction->currentData().toInt());
    options.cobId = input->cobId;
    options.dictionary = m_dictionary;

    QString status;
    const int chosen = m_protocol->currentData().toInt();
    if (chosen == kAuto) {
        const auto detection = vt::dev::inspect::detectProtocol(input->bytes, input->cobId);
        const vt::dev::inspect::Candidate *c = detection.choice();
        if (!c) {
            QStringList names;
            for (const auto &candidate : detection.candidates)
                names << protocolKey(candidate.protocol);
            m_detail->setUndescribed(bytes, QString());
            setStatus(names.isEmpty()
                          ? tr("Auto cannot decide: the bytes are no frame of any protocol "
                               "ValveTune knows. Choose a protocol to see why.")
                          : tr("Auto cannot decide between %1. Choose the protocol.")
                                .arg(names.join(QStringLiteral(", "))),
                      true);
            return;
        }
        options.protocol = c->protocol;
        // Keep the chosen direction and family when the bytes decode so; else the ones that do.
        if (!c->directions.empty() && std::find(c->directions.begin(), c->directions.end(),
                                                options.direction) == c->directions.end())
            options.direction = c->directions.front();
        if (!c->families.empty() &&
            std::find(c->families.begin(), c->families.end(), options.family) == c->families.end())
            options.family = c->families.front();
        const QString direction =
            options.direction == Direction::Request ? tr("request") : tr("response");
        status =
            c->badCrc
                ? tr("Auto: %1 (%2) with a wrong CRC.").arg(protocolKey(c->protocol), direction)
                : tr("Auto: %1 (%2).").arg(protocolKey(c->protocol), direction);
    } else {
        options.protocol = static_cast<FrameFormat>(chosen);
    }

    // A 16-byte CANopen paste is a SocketCAN image as the log records it.
    const bool socketCan = options.protocol == FrameFormat::Canopen && !input->cobId &&
                           input->bytes.size() == vt::dev::canopen::kSocketCanFrameSize;
    auto described = socketCan ? vt::dev::Result<vt::dev::Description, std::string>(
                                     vt::dev::inspect::describeSocketCanImage(input->bytes))
                               : vt::dev::describeAny(input->bytes, options);
    // A PLC process image: the gateway telegram followed by padding (DMA Profinet manual §4.5.4).
    if (options.protocol == FrameFormat::Gateway && described && described->error &&
        described->error->code == vt::dev::DecodeErrc::TooLong)
        described = vt::dev::inspect::describeLogged(vt::dev::LinkProtocol::NodeImage, input->bytes,
                                                     options);
    if (!described) {
        m_detail->setUndescribed(bytes, QString::fromStdString(described.error()));
        setStatus(QString::fromStdString(described.error()), true);
        return;
    }
    m_decoded = options.protocol;
    m_description = *described;
    m_detail->setFrame(bytes, m_description);
    if (m_description.error)
        status +=
            (status.isEmpty() ? QString() : QStringLiteral(" ")) + tr("The frame is not valid.");
    setStatus(status.isEmpty() ? tr("%n byte(s).", nullptr, static_cast<int>(bytes.size()))
                               : status,
              m_description.error.has_value());
}

void DecodePanel::retranslate()
{
    m_input->setPlaceholderText(tr("Hex bytes, e.g. 23 00 06 00 30 03 E8"));
    m_protocolLabel->setText(tr("Protocol:"));
    m_familyLabel->setText(tr("Family:"));
    m_directionLabel->setText(tr("Direction:"));
    m_protocol->setItemText(0, tr("auto"));
    m_direction->setItemText(0, tr("request (master → device)"));
    m_direction->setItemText(1, tr("response (device → master)"));
    decode();
}

void DecodePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace vt::ui
