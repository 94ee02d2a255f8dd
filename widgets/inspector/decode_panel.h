// DecodePanel: the inspector's decode box — paste or type a frame as hex (or candump
// "605#…"), pick a protocol or let "auto" pick one where the evidence is unambiguous, and see its
// fields and bytes. PLC traces included: CMD 15 images, PROFIdrive + CMD 15, PKW/PZD, HART, SDO.
#pragma once

#include "core/field_span.h"
#include "inspect/describe_any.h"

#include <QWidget>
#include <optional>

class QComboBox;
class QLabel;
class QPlainTextEdit;

namespace vt::dev {
struct Dictionary;
}

namespace vt::ui {

class FrameDetail;

class DecodePanel : public QWidget
{
    Q_OBJECT
public:
    explicit DecodePanel(QWidget *parent = nullptr);

    // Names HCS parameters in the fields (nullptr = raw IDs). Not owned; must outlive the panel.
    void setDictionary(const vt::dev::Dictionary *dictionary);
    void setFamily(vt::dev::hcs::Family family);

    void setText(const QString &text);
    QString text() const;
    // nullopt = auto.
    void setProtocol(std::optional<vt::dev::FrameFormat> protocol);
    void setDirection(vt::dev::Direction direction);

    // What the last decode found: the protocol used (nullopt when none), the status line and
    // the description shown.
    std::optional<vt::dev::FrameFormat> decodedProtocol() const { return m_decoded; }
    QString statusText() const;
    const vt::dev::Description &description() const { return m_description; }
    FrameDetail *detail() const { return m_detail; }

public slots:
    void decode();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void setStatus(const QString &text, bool problem);

    const vt::dev::Dictionary *m_dictionary = nullptr;
    QPlainTextEdit *m_input;
    QComboBox *m_protocol;
    QComboBox *m_family;
    QComboBox *m_direction;
    QLabel *m_protocolLabel;
    QLabel *m_familyLabel;
    QLabel *m_directionLabel;
    QLabel *m_status;
    FrameDetail *m_detail;
    std::optional<vt::dev::FrameFormat> m_decoded;
    vt::dev::Description m_description;
};

} // namespace vt::ui
