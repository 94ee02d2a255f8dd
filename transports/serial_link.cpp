#include "serial_link.h"

#include "link_log.h"
#include "serial_worker.h"

#include <QPointer>
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
    const QPointer<SerialWorker> worker = m_worker;
    if (m_thread.isRunning()) {
        // A worker on the worker thread is deleted there (finished → deleteLater runs there), so
        // its socket notifiers and port are released where they live.
        m_thread.quit();
        m_thread.wait();
    }
    // One that lives on this thread (exchanges without line timing) is deleted here.
    delete worker.data();
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
    // Queued from the worker thread; direct once the worker is on this thread (exchanges without
    // line timing). opened() and failed() stay queued: the link reacts outside the worker's calls.
    connect(m_worker, &SerialWorker::received, this, &SerialLink::onReceived, Qt::AutoConnection);
    connect(m_worker, &SerialWorker::wrote, this, &SerialLink::onWrote, Qt::AutoConnection);
    m_thread.start();
}

void SerialLink::takeWorkerHome()
{
    m_exchangesHere = false;
    // Runs where the worker is when it gets there: on this thread it moves the worker back, and
    // the calls queued after it follow the worker to its thread.
    QMetaObject::invokeMethod(
        m_worker,
        [worker = m_worker, home = &m_thread] {
            if (worker->thread() != home)
                worker->moveToThread(home);
        },
        Qt::QueuedConnection);
}

void SerialLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    ensureWorker();
    const quint64 session = ++m_session;
    setState(LinkState::Opening);
    takeWorkerHome();
    m_exchangesHereAtOpen = !m_settings.silentInterval && !m_settings.frameEndBySilence;
    QThread *exchangeThread = m_exchangesHereAtOpen ? thread() : nullptr;
    QMetaObject::invokeMethod(
        m_worker,
        [worker = m_worker, session, s = m_settings, exchangeThread] {
            worker->openPort(session, s, exchangeThread);
        },
        Qt::QueuedConnection);
}

void SerialLink::close()
{
    if (state() == LinkState::Closed)
        return;
    ++m_session;
    if (m_worker) {
        takeWorkerHome();
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
    if (m_exchangesHere) {
        m_worker->write(m_session, bytes, std::exchange(m_replyBytes, 0));
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
    m_exchangesHere = m_exchangesHereAtOpen; // the worker moved here before it said so
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

void SerialLink::onWrote(quint64 session, qint64 steadyNs)
{
    if (session == m_session && state() == LinkState::Open)
        emit frameOnWire(steadyNs);
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
