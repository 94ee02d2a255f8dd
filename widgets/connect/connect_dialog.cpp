#include "connect_dialog.h"

#include "widgets/connect/can_page.h"
#include "widgets/connect/connection_memory.h"
#include "widgets/connect/hart_page.h"
#include "widgets/connect/serial_page.h"
#include "widgets/connect/sim_page.h"
#include "widgets/connect/tcp_page.h"
#include "widgets/number_box.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QVBoxLayout>

namespace vt::ui {

ConnectDialog::ConnectDialog(const dev::DictionarySet &dictionaries, QSettings *memory,
                             QWidget *parent)
    : QDialog(parent), m_memory(memory)
{
    auto *layout = new QVBoxLayout(this);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("kinds"));
    m_pages = {new SerialPage(m_tabs), new TcpPage(m_tabs), new CanPage(m_tabs),
               new HartPage(m_tabs), new SimPage(dictionaries, m_tabs)};
    for (ConnectPage *p : m_pages) {
        m_tabs->addTab(p, p->title());
        connect(p, &ConnectPage::changed, this, &ConnectDialog::updateState);
        // A refused entry changes no value, yet it must block OK and say why.
        for (WholeNumberBox *box : p->findChildren<WholeNumberBox *>())
            connect(box, &QSpinBox::textChanged, this, &ConnectDialog::updateState);
    }
    layout->addWidget(m_tabs);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setTextFormat(Qt::PlainText);
    layout->addWidget(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->setObjectName(QStringLiteral("buttons"));
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);
    connect(m_tabs, &QTabWidget::currentChanged, this, &ConnectDialog::updateState);

    if (m_memory) {
        ConnectionMemory remembered(*m_memory);
        for (ConnectPage *p : m_pages)
            if (const auto spec = remembered.load(p->kind()))
                p->load(*spec);
        if (const auto last = remembered.lastKind())
            setKind(*last);
    }
    retranslate();
    updateState();
}

ConnectPage *ConnectDialog::page(model::ConnectionKind kind) const
{
    for (ConnectPage *p : m_pages)
        if (p->kind() == kind)
            return p;
    return nullptr;
}

ConnectPage *ConnectDialog::currentPage() const
{
    return static_cast<ConnectPage *>(m_tabs->currentWidget());
}

model::ConnectionSpec ConnectDialog::spec() const
{
    return currentPage()->spec();
}

void ConnectDialog::setSpec(const model::ConnectionSpec &spec)
{
    if (ConnectPage *p = page(spec.kind)) {
        p->load(spec);
        m_tabs->setCurrentWidget(p);
    }
    updateState();
}

model::ConnectionKind ConnectDialog::kind() const
{
    return currentPage()->kind();
}

void ConnectDialog::setKind(model::ConnectionKind kind)
{
    if (ConnectPage *p = page(kind))
        m_tabs->setCurrentWidget(p);
}

QString ConnectDialog::problem() const
{
    for (const WholeNumberBox *box : currentPage()->findChildren<WholeNumberBox *>())
        if (box->isVisibleTo(currentPage()) && !box->number())
            return box->refusal();
    return currentPage()->problem();
}

void ConnectDialog::accept()
{
    if (!problem().isEmpty())
        return;
    if (m_memory)
        ConnectionMemory(*m_memory).save(spec());
    QDialog::accept();
}

void ConnectDialog::updateState()
{
    const QString reason = problem();
    m_problem->setText(reason);
    m_problem->setVisible(!reason.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(reason.isEmpty());
}

void ConnectDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ConnectDialog::retranslate()
{
    setWindowTitle(tr("Connect"));
    for (int i = 0; i < m_tabs->count(); ++i)
        m_tabs->setTabText(i, static_cast<ConnectPage *>(m_tabs->widget(i))->title());
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("C&onnect"));
    // The pages may retranslate after the dialog: the reason is asked for again afterwards.
    QMetaObject::invokeMethod(this, &ConnectDialog::updateState, Qt::QueuedConnection);
}

} // namespace vt::ui
