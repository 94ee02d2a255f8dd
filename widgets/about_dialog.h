// AboutDialog: Help ▸ About — version, licence, the devices and manuals ValveTune covers.
#pragma once

#include <QDialog>

class QLabel;

namespace vt::ui {

class AboutDialog : public QDialog
{
    Q_OBJECT
public:
    explicit AboutDialog(QWidget *parent = nullptr);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QLabel *m_text = nullptr;
};

} // namespace vt::ui
