#include "about_dialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace vt::ui {

AboutDialog::AboutDialog(QWidget *parent) : QDialog(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setTextFormat(Qt::PlainText);
    m_text->setWordWrap(true);
    layout->addWidget(m_text);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    retranslate();
}

void AboutDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void AboutDialog::retranslate()
{
    setWindowTitle(tr("About ValveTune"));
    m_text->setText(
        tr("ValveTune %1\n\n"
           "Parameterisation, tuning and commissioning of hydraulic proportional-valve "
           "electronics: HCS OPAT and DMA-2, Wandfluh ED1/SD1 (DSP-408) and SD7 (HART-7).\n\n"
           "Licensed under the GNU General Public License, version 3 or later. "
           "Plots use QCustomPlot (GPL-3.0).")
            .arg(QCoreApplication::applicationVersion()));
}

} // namespace vt::ui
