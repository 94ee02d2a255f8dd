#include "serial_link.h"

#include "link_log.h"
#include "serial_worker.h"

#include <utility>

namespace vt::link {

SerialLink::SerialLink(SerialSettings settings, QObject *parent)
    : Link(parent), m_settings(std::move(settings))
{
    m_thread.setObjectName(QStringLiteral("vt-serial"));
}

SerialLink::~SerialLink()
{
    ++m_session;
    if (m_thread.isRunning()) {
        // The worker is deleted on its own thread (finished → deleteLater runs there), so its
        // socket notifier and port are released where they were created.
        m_thread.quit();
        m_thread.wait();
    }
}

void SerialLink::ensureWorker()
{
    if (m_worker)
        return;
    m_worker = new SerialWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &SerialWorker::opened, this, &SerialLink::onOpened, Qt::QueuedConnection);
    connect(m_worker, &SerialWorker::failed, this, &SerialLink::onFailed, Qt::QueuedConnection);
    connect(m_worker, &SerialWorker::received, this, &SerialLink::onReceived, Qt::QueuedConnection);
    m_thread.start();
}

void SerialLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    ensureWorker();
    const quint64 session = ++m_session;
    setState(LinkState::Opening);
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, session, s = m_settings] { worker->openPort(session, s); },
        Qt::QueuedConnection);
}

void SerialLink::close()
{
    if (state() == LinkState::Closed)
        return;
    ++m_session;
    if (m_worker) {
        QMetaObject::invokeMethod(
            m_worker, [worker = m_worker] { worker->closePort(); }, Qt::QueuedConnection);
    }
    setState(LinkState::Closed);
}

void SerialLink::send(const QByteArray &bytes)
{
    if (state() != LinkState::Open) {
        qCWarning(lcLink).noquote()
            << "send on" << description() << "while" << linkStateText(state()) << "- dropped"
            << bytes.size() << "bytes";
        return;
    }
    QMetaObject::invokeMethod(
        m_worker,
        [worker = m_worker, session = m_session, bytes, reply = std::exchange(m_replyBytes, 0)] {
            worker->write(session, bytes, reply);
        },
        Qt::QueuedConnection);
}

QString SerialLink::description() const
{
    return QStringLiteral("serial %1 %2 %3")
        .arg(m_settings.portName, QString::number(m_settings.baudRate), m_settings.formatText());
}

void SerialLink::onOpened(quint64 session)
{
    if (session != m_session || state() != LinkState::Opening)
        return;
    setState(LinkState::Open);
}

void SerialLink::onFailed(quint64 session, const QString &reason)
{
    if (session != m_session)
        return;
    if (state() != LinkState::Opening && state() != LinkState::Open)
        return;
    setState(LinkState::Failed);
    emit failed(reason);
}

void SerialLink::onReceived(quint64 session, const QByteArray &bytes, bool quiet)
{
    if (session != m_session || state() != LinkState::Open)
        return;
    if (!bytes.isEmpty())
        emit received(bytes);
    if (quiet && state() == LinkState::Open)
        emit lineQuiet();
}

} // namespace vt::link
