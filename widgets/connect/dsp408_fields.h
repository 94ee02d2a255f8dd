// Dsp408Fields: the connect dialog's settings of the Wandfluh ED1's PROFIBUS image over TCP
// (ARCHITECTURE.md "Wandfluh ED1/SD1 online"): where a PROFIBUS-master gateway maps the output and
// input images (first registers, FC 3 or FC 4), how its registers hold the image bytes, and the
// image layout both mappings share (PZD word order, IND byte; ED1/SD1 manual §4.5, §4.6).
#pragma once

#include "access/dsp408_adapter.h"

#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace vt::ui {

class Dsp408Fields : public QWidget
{
    Q_OBJECT
public:
    explicit Dsp408Fields(QWidget *parent = nullptr);

    void load(const dev::access::Dsp408LinkOptions &options);
    dev::access::Dsp408LinkOptions options() const;
    // The register rows apply to the gateway mapping only.
    void setGateway(bool gateway);

signals:
    void changed();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QFormLayout *m_form = nullptr;
    QSpinBox *m_output = nullptr;
    QSpinBox *m_input = nullptr;
    QComboBox *m_function = nullptr;
    QComboBox *m_bytes = nullptr;
    QComboBox *m_words = nullptr;
    QComboBox *m_ind = nullptr;
    QLabel *m_outputLabel = nullptr;
    QLabel *m_inputLabel = nullptr;
    QLabel *m_functionLabel = nullptr;
    QLabel *m_bytesLabel = nullptr;
    QLabel *m_wordsLabel = nullptr;
    QLabel *m_indLabel = nullptr;
};

} // namespace vt::ui
