#include "welcome_page.h"

#include <QCommandLinkButton>
#include <QEvent>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace vt::app {

WelcomePage::WelcomePage(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("welcomePage"));
    m_title = new QLabel(this);
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.5);
    big.setBold(true);
    m_title->setFont(big);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    auto button = [this](const char *name, void (WelcomePage::*signal)()) {
        auto *b = new QCommandLinkButton(this);
        b->setObjectName(QString::fromLatin1(name));
        connect(b, &QCommandLinkButton::clicked, this, signal);
        return b;
    };
    m_connect = button("welcomeConnect", &WelcomePage::connectRequested);
    m_open = button("welcomeOpen", &WelcomePage::openRequested);
    m_new = button("welcomeNew", &WelcomePage::newRequested);
    m_simulator = button("welcomeSimulator", &WelcomePage::simulatorRequested);

    auto *column = new QVBoxLayout;
    column->addWidget(m_title);
    column->addWidget(m_intro);
    for (QWidget *w : {m_connect, m_open, m_new, m_simulator})
        column->addWidget(w);
    auto *centre = new QWidget;
    centre->setLayout(column);
    // Wide enough that each description stays on one line (a command link button does not
    // grow for a second one).
    centre->setMinimumWidth(780);
    // The bottom docks may leave little height: the buttons keep theirs and the page scrolls.
    auto *page = new QWidget;
    auto *pageLayout = new QVBoxLayout(page);
    pageLayout->addWidget(centre, 0, Qt::AlignHCenter);
    pageLayout->addStretch(1);
    auto *scroll = new QScrollArea(this);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setWidget(page);
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
    retranslate();
}

void WelcomePage::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void WelcomePage::retranslate()
{
    m_title->setText(tr("Welcome to ValveTune"));
    m_intro->setText(tr("No device is connected and no parameter file is open. Start with one "
                        "of these:"));
    m_connect->setText(tr("Connect…"));
    m_connect->setDescription(tr("Reach a node or module over serial, TCP, CAN or HART."));
    m_open->setText(tr("Open…"));
    m_open->setDescription(tr("Open a parameter file (.vtpar) or a fold plan (.vtfold)."));
    m_new->setText(tr("New…"));
    m_new->setDescription(
        tr("Make a parameter file for a module type and version, without a device."));
    m_simulator->setText(tr("Try the simulator…"));
    m_simulator->setDescription(
        tr("Connect to a built-in simulated node: every window works, no valve moves."));
}

} // namespace vt::app
