#include "hcs_product_box.h"

#include <QEvent>

namespace vt::ui {

namespace {

constexpr dev::HcsProduct kProducts[] = {dev::HcsProduct::Unknown, dev::HcsProduct::Opat,
                                         dev::HcsProduct::DmaProfinet,
                                         dev::HcsProduct::DmaProfibus};

} // namespace

HcsProductBox::HcsProductBox(QWidget *parent) : QComboBox(parent)
{
    for (dev::HcsProduct p : kProducts)
        addItem(QString(), static_cast<int>(p));
    retranslate();
}

dev::HcsProduct HcsProductBox::product() const
{
    return static_cast<dev::HcsProduct>(currentData().toInt());
}

void HcsProductBox::setProduct(dev::HcsProduct product)
{
    const int index = findData(static_cast<int>(product));
    setCurrentIndex(index < 0 ? 0 : index);
}

void HcsProductBox::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QComboBox::changeEvent(event);
}

void HcsProductBox::retranslate()
{
    for (int i = 0; i < count(); ++i) {
        switch (static_cast<dev::HcsProduct>(itemData(i).toInt())) {
        case dev::HcsProduct::Unknown: setItemText(i, tr("Tell from the version")); break;
        case dev::HcsProduct::Opat: setItemText(i, tr("HCS OPAT")); break;
        case dev::HcsProduct::DmaProfinet: setItemText(i, tr("HCS DMA-2 PROFINET")); break;
        case dev::HcsProduct::DmaProfibus: setItemText(i, tr("HCS DMA-2 PROFIBUS")); break;
        }
    }
}

} // namespace vt::ui
