#include "link_status_widget.h"

#include "model/session/connection.h"
#include "model/text_language.h"
#include "transports/link.h"
#include "widgets/connect/language_text.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QStringList>

namespace vt::ui {

namespace {

// Counters change with every request (the monitor polls many times a second); people read ten
// updates a second at most.
constexpr int kRefreshMs = 100;
// The status bar keeps room for messages: link and identity give up their tails (whole on hover).
constexpr int kLinkWidthPx = 240;
constexpr int kIdentityWidthPx = 260;
constexpr const char *kFullText = "vtFullText";

void setElided(QLabel *label, const QString &full, int widthPx, const QString &moreTip = {})
{
    label->setProperty(kFullText, full);
    label->setText(label->fontMetrics().elidedText(full, Qt::ElideRight, widthPx));
    label->setToolTip(moreTip.isEmpty() ? full : full + QStringLiteral("\n\n") + moreTip);
}

} // namespace

LinkStatusWidget::LinkStatusWidget(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_link = new QLabel(this);
    m_link->setObjectName(QStringLiteral("link"));
    m_identity = new QLabel(this);
    m_identity->setObjectName(QStringLiteral("identity"));
    m_counters = new QLabel(this);
    m_counters->setObjectName(QStringLiteral("counters"));
    for (QLabel *label : {m_link, m_identity, m_counters}) {
        label->setTextFormat(Qt::PlainText);
        layout->addWidget(label);
    }
    m_refresh.setSingleShot(true);
    m_refresh.setInterval(kRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, &LinkStatusWidget::refresh);
    refresh();
}

void LinkStatusWidget::setConnection(model::Connection *connection,
                                     const std::vector<model::ModuleInfo> &modules)
{
    clearConnection();
    m_connection = connection;
    m_modules = modules;
    if (connection) {
        connect(&connection->link(), &link::Link::stateChanged, this,
                [this](link::LinkState state) {
                    if (state == link::LinkState::Open)
                        m_reason.clear();
                    scheduleRefresh();
                });
        const auto failed = [this](const QString &reason) {
            m_reason = reason;
            scheduleRefresh();
        };
        connect(connection, &model::Connection::failed, this, failed);
        connect(connection, &model::Connection::lost, this, failed);
        // Deferred, never inline: the connection's destructor closes the link after its session
        // is gone, and refresh() asks the session for its counters.
        connect(&connection->session(), &model::Session::countersChanged, this,
                &LinkStatusWidget::scheduleRefresh);
        connect(connection, &QObject::destroyed, this, &LinkStatusWidget::clearConnection);
    }
    refresh();
}

void LinkStatusWidget::setModules(const std::vector<model::ModuleInfo> &modules)
{
    m_modules = modules;
    refresh();
}

void LinkStatusWidget::clearConnection()
{
    if (m_connection) {
        m_connection->disconnect(this);
        m_connection->link().disconnect(this);
        m_connection->session().disconnect(this);
    }
    m_connection = nullptr;
    m_modules.clear();
    m_reason.clear();
    m_refresh.stop();
    refresh();
}

void LinkStatusWidget::scheduleRefresh()
{
    if (!m_refresh.isActive())
        m_refresh.start();
}

QString LinkStatusWidget::linkText() const
{
    const QVariant full = m_link->property(kFullText);
    return full.isValid() ? full.toString() : m_link->text();
}

QString LinkStatusWidget::identityText() const
{
    return m_identity->property(kFullText).toString();
}

QString LinkStatusWidget::countersText() const
{
    return m_counters->text();
}

QString LinkStatusWidget::moduleText(const model::ModuleInfo &module) const
{
    const QLocale locale;
    QString what = model::localText(module.identityText);
    if (what.isEmpty()) {
        what = module.dictionary ? model::localText(module.dictionary->title)
                                 : QString::fromStdString(module.identification.family);
        if (!module.identification.version.empty())
            what = tr("%1, V%2").arg(what, QString::fromStdString(module.identification.version));
    }
    if (!module.identification.mode.empty())
        what = tr("%1, mode %2").arg(what, QString::fromStdString(module.identification.mode));
    QString text = tr("#%1 %2").arg(locale.toString(module.address), what);
    if (!module.identification.exact)
        text = tr("%1 (nearest match)").arg(text);
    return text;
}

void LinkStatusWidget::refresh()
{
    const QLocale locale;
    if (!m_connection) {
        m_link->setText(link::linkStateText(link::LinkState::Closed));
        m_link->setProperty(kFullText, QVariant());
        m_link->setToolTip(QString());
        m_identity->clear();
        m_identity->setProperty(kFullText, QString());
        m_identity->setToolTip(QString());
        m_identity->hide();
        m_counters->clear();
        m_counters->hide();
        return;
    }
    // describe() is for logs and stays untranslated; the window shows displayText().
    QString state = link::linkStateText(m_connection->link().state());
    if (!m_reason.isEmpty())
        state = tr("%1: %2").arg(state, m_reason);
    setElided(m_link, tr("%1 — %2").arg(m_connection->displayText(), state), kLinkWidthPx);

    QStringList modules;
    QStringList warnings;
    for (const model::ModuleInfo &module : m_modules) {
        modules << moduleText(module);
        if (!module.identification.warning.en.empty())
            warnings << model::localText(module.identification.warning);
    }
    setElided(m_identity, modules.join(QStringLiteral("; ")), kIdentityWidthPx,
              warnings.join(QLatin1Char('\n')));
    m_identity->setVisible(!modules.isEmpty());

    const model::SessionCounters &c = m_connection->session().counters();
    m_counters->setText(tr("requests %1 · retries %2 · timeouts %3 · refused %4 · failed %5")
                            .arg(locale.toString(c.requests), locale.toString(c.retries),
                                 locale.toString(c.timeouts), locale.toString(c.exceptions),
                                 locale.toString(c.failures)));
    m_counters->setToolTip(tr("Frames sent: %1. Refused: the device answered with an exception. "
                              "Failed: no answer after every retry, or the link was lost.")
                               .arg(locale.toString(c.attempts)));
    m_counters->show();
}

void LinkStatusWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QWidget::changeEvent(event);
}

} // namespace vt::ui
