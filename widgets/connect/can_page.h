// CanPage: a module on a CAN bus through SocketCAN, CANopen SDO — interface, node id and the
// object mapping (HCS manufacturer area, or a Wandfluh ED1 with CiA 408 objects).
#pragma once

#include "widgets/connect/connect_page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vt::ui {

class HcsProductBox;

class CanPage : public ConnectPage
{
    Q_OBJECT
public:
    explicit CanPage(QWidget *parent = nullptr);

    model::ConnectionKind kind() const override { return model::ConnectionKind::Can; }
    QString title() const override;
    void load(const model::ConnectionSpec &spec) override;
    model::ConnectionSpec spec() const override;
    QString problem() const override;

protected:
    void retranslate() override;

private:
    void updateEnabled();

    QLineEdit *m_interface = nullptr;
    QSpinBox *m_node = nullptr;
    QComboBox *m_device = nullptr;
    HcsProductBox *m_product = nullptr;
    QLabel *m_interfaceLabel = nullptr;
    QLabel *m_nodeLabel = nullptr;
    QLabel *m_deviceLabel = nullptr;
    QLabel *m_productLabel = nullptr;
};

} // namespace vt::ui
