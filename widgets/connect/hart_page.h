// HartPage: a Wandfluh SD7 through a HART modem — serial port, the fixed line (1200 baud 8O1,
// ARCHITECTURE.md "HART") and the poll address.
#pragma once

#include "widgets/connect/connect_page.h"

class QLabel;
class QSpinBox;

namespace vt::ui {

class SerialPortBox;

class HartPage : public ConnectPage
{
    Q_OBJECT
public:
    explicit HartPage(QWidget *parent = nullptr);

    model::ConnectionKind kind() const override { return model::ConnectionKind::Hart; }
    QString title() const override;
    void load(const model::ConnectionSpec &spec) override;
    model::ConnectionSpec spec() const override;
    QString problem() const override;

protected:
    void retranslate() override;

private:
    SerialPortBox *m_port = nullptr;
    QLabel *m_line = nullptr;
    QSpinBox *m_poll = nullptr;
    QLabel *m_portLabel = nullptr;
    QLabel *m_lineLabel = nullptr;
    QLabel *m_pollLabel = nullptr;
};

} // namespace vt::ui
