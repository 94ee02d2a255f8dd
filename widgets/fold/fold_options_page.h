// Fold wizard page 4: the bus options of each module — E17 set value source, E23 bus telegram
// timeout, and on the OPAT E26 CAN baud rate and E28 lost-slave behaviour — with the labels,
// ranges and the manual's explanation of each from the module's dictionary. An option left
// unticked is not written and not shown on the PLC sheet.
#pragma once

#include "widgets/fold/fold_page.h"

class QScrollArea;
class QVBoxLayout;
class QWidget;

namespace vt::ui {

class FoldOptionsPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldOptionsPage(QWidget *parent = nullptr);
    void initializePage() override;

protected:
    void retranslate() override;

private:
    void rebuild();

    QScrollArea *m_scroll = nullptr;
    QWidget *m_content = nullptr;
};

} // namespace vt::ui
