// Fold wizard page 3: the address of every module — DMA E22 = 1..n from the left (CMD 15 reaches
// 1..5 only), OPAT master SADR 0 and slaves 1..7 by rotary switch (the page says which position
// to set) — and the OPAT master's PROFIBUS address E24 with the "126 = set by the master" rule.
#pragma once

#include "widgets/fold/fold_page.h"

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace vt::ui {

class FoldAddressPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldAddressPage(QWidget *parent = nullptr);
    void initializePage() override;

protected:
    void retranslate() override;

private:
    void fillTable();
    void updateGuide();
    void numberLeftToRight();

    QLabel *m_rule = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_number = nullptr;
    QCheckBox *m_setE24 = nullptr;
    QSpinBox *m_e24 = nullptr;
    QLabel *m_e24Note = nullptr;
    bool m_filling = false;
};

} // namespace vt::ui
