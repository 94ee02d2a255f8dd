// SerialPage: HCS modules over a serial line (RS232 point-to-point or RS485), Modbus RTU —
// port, line settings (HCS default 19200 8E1), module address and product.
#pragma once

#include "widgets/connect/connect_page.h"

class QLabel;
class QSpinBox;

namespace vt::ui {

class HcsProductBox;
class SerialLineFields;
class SerialPortBox;

class SerialPage : public ConnectPage
{
    Q_OBJECT
public:
    explicit SerialPage(QWidget *parent = nullptr);

    model::ConnectionKind kind() const override { return model::ConnectionKind::Serial; }
    QString title() const override;
    void load(const model::ConnectionSpec &spec) override;
    model::ConnectionSpec spec() const override;
    QString problem() const override;

protected:
    void retranslate() override;

private:
    SerialPortBox *m_port = nullptr;
    SerialLineFields *m_line = nullptr;
    QSpinBox *m_address = nullptr;
    HcsProductBox *m_product = nullptr;
    QLabel *m_portLabel = nullptr;
    QLabel *m_addressLabel = nullptr;
    QLabel *m_productLabel = nullptr;
    // Modbus RTU line timing (SerialSettings): on unless the loaded spec turned it off.
    bool m_silentInterval = true;
    bool m_frameEndBySilence = true;
};

} // namespace vt::ui
