// Fold wizard page 1: which kind of node — OPAT master with CAN slaves, DMA-2 on PROFIBUS, DMA-2
// on PROFINET — and, for DMA PROFIBUS, the node's product number that decides the GSD file.
#pragma once

#include "widgets/fold/fold_page.h"

class QButtonGroup;
class QLabel;
class QLineEdit;
class QRadioButton;

namespace vt::ui {

class FoldNodePage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldNodePage(QWidget *parent = nullptr);
    void initializePage() override;
    bool validatePage() override;

protected:
    void retranslate() override;

private:
    void updateDetails();

    QButtonGroup *m_group = nullptr;
    QRadioButton *m_buttons[3] = {};
    QLabel *m_details = nullptr;
    QLabel *m_productLabel = nullptr;
    QLineEdit *m_product = nullptr;
};

} // namespace vt::ui
