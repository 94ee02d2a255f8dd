// HcsProductBox: which HCS product sits at the other end of a link. Version numbers overlap (V31
// is an OPAT CAN slave and a DMA-2 PROFIBUS), and OPAT and DMA-2 have their own exception codes,
// so a link that cannot tell needs the user's word (dict/identify.h).
#pragma once

#include "dict/identify.h"

#include <QComboBox>

namespace vt::ui {

class HcsProductBox : public QComboBox
{
    Q_OBJECT
public:
    explicit HcsProductBox(QWidget *parent = nullptr);

    dev::HcsProduct product() const;
    void setProduct(dev::HcsProduct product);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
};

} // namespace vt::ui
