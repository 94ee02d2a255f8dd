// TcpPage: a gateway or the simulator over TCP — host, port, Modbus TCP or the node image
// (the fixed-length telegrams a PLC exchanges, ARCHITECTURE.md), module address and product; or
// the Wandfluh ED1's PROFIBUS image, raw or through a gateway's registers, with its mapping.
#pragma once

#include "widgets/connect/connect_page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vt::ui {

class Dsp408Fields;
class HcsProductBox;

class TcpPage : public ConnectPage
{
    Q_OBJECT
public:
    explicit TcpPage(QWidget *parent = nullptr);

    model::ConnectionKind kind() const override { return model::ConnectionKind::Tcp; }
    QString title() const override;
    void load(const model::ConnectionSpec &spec) override;
    model::ConnectionSpec spec() const override;
    QString problem() const override;

protected:
    void retranslate() override;

private:
    // Shows the fields the chosen protocol uses.
    void fitProtocol();

private:
    QLineEdit *m_host = nullptr;
    QSpinBox *m_port = nullptr;
    QComboBox *m_protocol = nullptr;
    QSpinBox *m_address = nullptr;
    HcsProductBox *m_product = nullptr;
    Dsp408Fields *m_dsp408 = nullptr; // the ED1's image (dsp408-image, dsp408-gateway)
    QLabel *m_hostLabel = nullptr;
    QLabel *m_portLabel = nullptr;
    QLabel *m_protocolLabel = nullptr;
    QLabel *m_addressLabel = nullptr;
    QLabel *m_productLabel = nullptr;
};

} // namespace vt::ui
