// SerialPortBox: a serial port picked from the enumerated ports (transports/serial_ports.h) or
// typed as a path ("/dev/ttyUSB0", a pty), with a button to enumerate again.
#pragma once

#include <QString>
#include <QWidget>

class QComboBox;
class QToolButton;

namespace vt::ui {

class SerialPortBox : public QWidget
{
    Q_OBJECT
public:
    // `name`: the object-name prefix of the children ("serial" → "serialPort", "serialRefresh").
    explicit SerialPortBox(const QString &name, QWidget *parent = nullptr);

    // The device path, trimmed; empty when none is chosen or typed.
    QString portName() const;
    void setPortName(const QString &name);
    // Enumerates the ports again, keeping what is typed.
    void refresh();

signals:
    void changed();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QComboBox *m_combo = nullptr;
    QToolButton *m_refresh = nullptr;
};

} // namespace vt::ui
