// SerialLineFields: the line settings of a serial port — baud rate (a common rate or a typed
// one), data bits, parity and stop bits — as rows for a QFormLayout.
#pragma once

#include "model/number_text.h"
#include "transports/serial_settings.h"

#include <QObject>
#include <QString>

class QComboBox;
class QFormLayout;
class QLabel;
class QWidget;

namespace vt::ui {

class SerialLineFields : public QObject
{
    Q_OBJECT
public:
    // Adds four rows to `form`; the widgets are children of `owner` and named
    // "<name>Baud", "<name>DataBits", "<name>Parity", "<name>StopBits".
    SerialLineFields(const QString &name, QFormLayout *form, QWidget *owner);

    // The line settings for `portName`; baudRate is 0 when the typed rate is not a number.
    link::SerialSettings settings(const QString &portName) const;
    void setSettings(const link::SerialSettings &settings);
    // Why the typed baud rate is unusable, or empty.
    QString problem() const;
    void retranslate();

signals:
    void changed();

private:
    int baudRate() const;
    model::NumberParse parsedBaudRate() const;

    QComboBox *m_baud = nullptr;
    QComboBox *m_dataBits = nullptr;
    QComboBox *m_parity = nullptr;
    QComboBox *m_stopBits = nullptr;
    QLabel *m_baudLabel = nullptr;
    QLabel *m_dataBitsLabel = nullptr;
    QLabel *m_parityLabel = nullptr;
    QLabel *m_stopBitsLabel = nullptr;
};

} // namespace vt::ui
