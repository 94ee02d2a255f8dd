// TcpPage: a gateway or the simulator over TCP — host, port, Modbus TCP or the node image
// (the fixed-length telegrams a PLC exchanges, ARCHITECTURE.md), module address and product.
#pragma once

#include "widgets/connect/connect_page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vt::ui {

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
    QLineEdit *m_host = nullptr;
    QSpinBox *m_port = nullptr;
    QComboBox *m_protocol = nullptr;
    QSpinBox *m_address = nullptr;
    HcsProductBox *m_product = nullptr;
    QLabel *m_hostLabel = nullptr;
    QLabel *m_portLabel = nullptr;
    QLabel *m_protocolLabel = nullptr;
    QLabel *m_addressLabel = nullptr;
    QLabel *m_productLabel = nullptr;
};

} // namespace vt::ui
