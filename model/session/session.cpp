#include "session.h"

#include "model/text_language.h"
#include "transports/byte_span.h"
#include "transports/link.h"

#include <QSignalBlocker>
#include <utility>

namespace vt::model {

namespace {

constexpr qsizetype kMaxUnmatched = 4096;

struct ApiGuard
{
    explicit ApiGuard(int &depth) : m_depth(depth) { ++m_depth; }
    ~ApiGuard() { --m_depth; }
    ApiGuard(const ApiGuard &) = delete;
    ApiGuard &operator=(const ApiGuard &) = delete;
    int &m_depth;
};

} // namespace

Session::Session(link::Link *link, std::unique_ptr<dev::access::ProtocolAdapter> adapter,
                 SessionOptions options, QObject *parent)
    : QObject(parent), m_link(link), m_adapter(std::move(adapter)), m_options(options)
{
    m_clock.start();
    m_timeout.setSingleShot(true);
    m_timeout.setTimerType(Qt::PreciseTimer);
    m_backoff.setSingleShot(true);
    m_backoff.setTimerType(Qt::PreciseTimer);
    m_cycle.setSingleShot(true);
    m_cycle.setTimerType(Qt::PreciseTimer);
    connect(&m_timeout, &QTimer::timeout, this, &Session::onTimeout);
    connect(&m_cycle, &QTimer::timeout, this, &Session::sendFollowUp);
    connect(&m_backoff, &QTimer::timeout, this, [this] {
        if (m_current)
            sendAttempt();
    });
    connect(m_link, &link::Link::received, this, &Session::onReceived);
    connect(m_link, &link::Link::lineQuiet, this, [this] {
        m_adapter->lineQuiet(m_current && m_timeout.isActive() ? &m_current->transaction : nullptr);
    });
    connect(m_link, &link::Link::stateChanged, this, &Session::onLinkState);
    connect(m_link, &link::Link::failed, this, &Session::onLinkFailed);
}

Session::~Session()
{
    m_destroying = true;
    const QSignalBlocker quiet(this);
    m_timeout.stop();
    m_backoff.stop();
    m_cycle.stop();
    disconnect(m_link, nullptr, this, nullptr);
    // Completions may submit or cancel while this runs: loop until nothing is left.
    for (;;) {
        if (!m_deferred.empty()) {
            deliverDeferred();
            continue;
        }
        std::unique_ptr<Pending> pending = takeAnyPending();
        if (!pending)
            break;
        ++m_counters.requests;
        const Outcome outcome{
            OutcomeStatus::Cancelled, {}, pending->attempts, pending->sent, tr("Cancelled")};
        const Completion done = std::move(pending->done);
        pending.reset();
        if (done)
            done(outcome);
    }
}

std::unique_ptr<Session::Pending> Session::takeAnyPending()
{
    if (m_current)
        return std::move(m_current);
    for (auto *queue : {&m_user, &m_monitor}) {
        if (!queue->empty()) {
            auto pending = std::move(queue->front());
            queue->pop_front();
            return pending;
        }
    }
    return nullptr;
}

bool Session::linkOpen() const
{
    return m_link->state() == link::LinkState::Open;
}

RequestId Session::submit(dev::access::Transaction t, Priority priority, Completion done)
{
    const ApiGuard guard(m_apiDepth);
    auto pending = std::make_unique<Pending>();
    pending->id = m_nextId++;
    pending->transaction = std::move(t);
    pending->priority = priority;
    pending->done = std::move(done);
    const RequestId id = pending->id;
    if (queued() >= m_options.maxQueued) {
        finish(std::move(pending),
               Outcome{OutcomeStatus::Cancelled, {}, 0, false, tr("The request queue is full")});
        return id;
    }
    (priority == Priority::User ? m_user : m_monitor).push_back(std::move(pending));
    schedule();
    return id;
}

void Session::cancel(RequestId id)
{
    const ApiGuard guard(m_apiDepth);
    if (m_current && m_current->id == id) {
        m_current->cancelled = true;
        return;
    }
    for (auto *queue : {&m_user, &m_monitor}) {
        for (auto it = queue->begin(); it != queue->end(); ++it) {
            if ((*it)->id == id) {
                auto pending = std::move(*it);
                queue->erase(it);
                finish(std::move(pending),
                       Outcome{OutcomeStatus::Cancelled, {}, 0, false, tr("Cancelled")});
                return;
            }
        }
    }
}

void Session::cancelAll(Priority priority)
{
    const ApiGuard guard(m_apiDepth);
    auto &queue = priority == Priority::User ? m_user : m_monitor;
    auto taken = std::move(queue);
    queue.clear();
    for (auto &pending : taken)
        finish(std::move(pending),
               Outcome{OutcomeStatus::Cancelled, {}, 0, false, tr("Cancelled")});
    if (m_current && m_current->priority == priority)
        m_current->cancelled = true;
}

void Session::schedule()
{
    if (m_current || m_startScheduled || m_destroying)
        return;
    m_startScheduled = true;
    QTimer::singleShot(0, this, [this] {
        m_startScheduled = false;
        startNext();
    });
}

void Session::startNext()
{
    if (m_current || m_destroying)
        return;
    if (m_user.empty() && m_monitor.empty()) {
        emit idle();
        return;
    }
    const auto state = m_link->state();
    if (state == link::LinkState::Opening)
        return; // onLinkState(Open) schedules again
    if (state != link::LinkState::Open) {
        failEverything(OutcomeStatus::LinkLost,
                       tr("The link %1 is not open").arg(m_link->description()));
        return;
    }
    auto &queue = m_user.empty() ? m_monitor : m_user;
    m_current = std::move(queue.front());
    queue.pop_front();
    sendAttempt();
}

void Session::sendAttempt()
{
    // A request that ends here (cancelled, not encodable, no reply expected) completes from the
    // event loop: a long run of them must not recurse finish() → startNext() → sendAttempt().
    const ApiGuard guard(m_apiDepth);
    Pending &p = *m_current;
    if (p.cancelled) {
        finish(std::move(m_current),
               Outcome{OutcomeStatus::Cancelled, {}, p.attempts, p.sent, tr("Cancelled")});
        return;
    }
    m_cycle.stop();
    m_adapter->resetFraming();
    m_unmatched.clear();
    const dev::Bytes bytes = m_adapter->encode(p.transaction);
    if (bytes.empty()) {
        finish(std::move(m_current),
               Outcome{OutcomeStatus::NotEncodable,
                       {},
                       p.attempts,
                       p.sent,
                       tr("The request cannot be encoded for %1")
                           .arg(QString::fromLatin1(dev::key(m_adapter->protocol())))});
        return;
    }
    ++p.attempts;
    p.sent = true;
    ++m_counters.attempts;
    if (p.attempts > 1)
        ++m_counters.retries;
    const QByteArray frame = link::toByteArray(bytes);
    // Read before frameSent: a slot may end the link at once, and with it this request (`p`).
    const bool answered =
        p.transaction.kind != dev::access::TransactionKind::Raw || p.transaction.expectsReply;
    const auto replyBytes =
        answered ? static_cast<qsizetype>(m_adapter->expectedReplyBytes(p.transaction)) : 0;
    emit frameSent(frame, p.transaction.module, elapsedNs());
    m_link->expectReply(replyBytes);
    m_link->send(frame);
    // A link may fail inside send() (FaultLink's cut, a serial write error) and report it at
    // once: failEverything() has then completed this request and `p` is gone.
    if (!m_current)
        return;
    if (!answered) {
        finish(std::move(m_current), Outcome{OutcomeStatus::Ok, {}, p.attempts, true, {}});
        return;
    }
    m_timeout.start(m_options.timeout(bytes.size(), static_cast<std::size_t>(replyBytes)));
}

void Session::onReceived(const QByteArray &bytes)
{
    if (!m_current || !m_timeout.isActive()) {
        emit frameReceived(bytes, -1, elapsedNs(), ReceivedKind::Unsolicited, tr("unsolicited"));
        return;
    }
    Pending &p = *m_current;
    m_unmatched.append(bytes);
    if (m_unmatched.size() > kMaxUnmatched) // a babbling line must not grow memory
        m_unmatched.remove(0, m_unmatched.size() - kMaxUnmatched);
    auto reply = m_adapter->feed(link::byteSpan(bytes), p.transaction);
    if (!reply)
        return;
    m_unmatched.clear();
    if (reply->status == dev::access::ReplyStatus::Mismatch) {
        emit frameReceived(link::toByteArray(reply->frame), p.transaction.module, elapsedNs(),
                           ReceivedKind::Unmatched, tr("does not answer the request"));
        return;
    }
    if (reply->status == dev::access::ReplyStatus::Progress) {
        // The attempt's timeout keeps running: a device that never answers ends it as usual.
        emit frameReceived(link::toByteArray(reply->frame), p.transaction.module, elapsedNs(),
                           ReceivedKind::Answer, tr("exchange in progress"));
        m_followUp = std::move(reply->next);
        if (m_followUp.empty())
            return;
        if (reply->nextAfterCycle)
            m_cycle.start(m_options.busCycle);
        else
            sendFollowUp();
        return;
    }
    m_timeout.stop();
    m_cycle.stop();
    const bool refused = reply->status == dev::access::ReplyStatus::DeviceException;
    // An answer with a code is a warning (HART common codes such as 14): the value arrived, and
    // the log says what the device added to it.
    const bool warned = !refused && reply->exceptionCode != 0;
    emit frameReceived(
        link::toByteArray(reply->frame), p.transaction.module, elapsedNs(),
        refused ? ReceivedKind::Exception : ReceivedKind::Answer,
        refused ? localText(reply->exceptionText)
        : warned
            ? tr("warning %1: %2").arg(reply->exceptionCode).arg(localText(reply->exceptionText))
            : QString());
    if (p.cancelled) {
        finish(std::move(m_current), Outcome{OutcomeStatus::Cancelled, std::move(*reply),
                                             p.attempts, true, tr("Cancelled")});
        return;
    }
    Outcome outcome{refused ? OutcomeStatus::DeviceException : OutcomeStatus::Ok,
                    std::move(*reply),
                    p.attempts,
                    true,
                    {}};
    if (refused)
        ++m_counters.exceptions;
    finish(std::move(m_current), std::move(outcome));
}

void Session::sendFollowUp()
{
    if (!m_current || !m_timeout.isActive() || m_followUp.empty())
        return;
    const QByteArray frame = link::toByteArray(std::exchange(m_followUp, {}));
    emit frameSent(frame, m_current->transaction.module, elapsedNs());
    m_link->expectReply(0); // the exchange's next frame: its size is the adapter's business
    m_link->send(frame);
}

void Session::onTimeout()
{
    if (!m_current)
        return;
    m_cycle.stop();
    Pending &p = *m_current;
    ++m_counters.timeouts;
    if (!m_unmatched.isEmpty()) {
        emit frameReceived(m_unmatched, p.transaction.module, elapsedNs(), ReceivedKind::Garbage,
                           tr("no valid frame (checksum error, corrupted or incomplete)"));
        m_unmatched.clear();
    }
    emit attemptTimedOut(p.transaction.module, p.attempts, elapsedNs());
    if (p.cancelled) {
        finish(std::move(m_current),
               Outcome{OutcomeStatus::Cancelled, {}, p.attempts, true, tr("Cancelled")});
        return;
    }
    if (p.attempts <= m_options.retries) {
        emit countersChanged();
        m_backoff.start(m_options.backoffBefore(p.attempts));
        return;
    }
    ++m_counters.failures;
    finish(std::move(m_current), Outcome{OutcomeStatus::Timeout,
                                         {},
                                         p.attempts,
                                         true,
                                         tr("No answer after %n attempt(s)", nullptr, p.attempts)});
}

void Session::onLinkState(link::LinkState state)
{
    if (state == link::LinkState::Open) {
        schedule();
        return;
    }
    if (state == link::LinkState::Closed || state == link::LinkState::Failed)
        failEverything(OutcomeStatus::LinkLost,
                       tr("The link %1 was lost").arg(m_link->description()));
}

void Session::onLinkFailed(const QString &reason)
{
    failEverything(OutcomeStatus::LinkLost, reason);
}

void Session::failEverything(OutcomeStatus status, const QString &reason)
{
    const ApiGuard guard(m_apiDepth);
    m_timeout.stop();
    m_backoff.stop();
    m_cycle.stop();
    if (m_current) {
        const int attempts = m_current->attempts;
        const bool sent = m_current->sent;
        ++m_counters.failures;
        finish(std::move(m_current), Outcome{status, {}, attempts, sent, reason});
    }
    for (auto *queue : {&m_user, &m_monitor}) {
        auto taken = std::move(*queue);
        queue->clear();
        for (auto &pending : taken) {
            ++m_counters.failures;
            finish(std::move(pending), Outcome{status, {}, 0, false, reason});
        }
    }
}

void Session::finish(std::unique_ptr<Pending> pending, Outcome outcome)
{
    ++m_counters.requests;
    emit countersChanged();
    auto done = std::move(pending->done);
    pending.reset();
    if (m_apiDepth > 0) {
        // Inside submit()/cancel()/a link failure: the caller must not see its completion
        // before the call returns. Completions run from the event loop, in order.
        m_deferred.emplace_back(std::move(done), std::move(outcome));
        // One event per completion, as each was posted when it was decided: a completion that
        // runs the event loop (a modal progress dialog) sees the next ones arrive inside it. A
        // completion may destroy the session: its destructor delivers the rest, and the events
        // still posted go with it.
        if (!m_destroying)
            QTimer::singleShot(0, this, [this] {
                if (!m_deferred.empty())
                    deliverDeferred();
            });
        schedule();
        return;
    }
    // From the event loop (an answer or a timeout): complete at once and put the next request on
    // the wire without another event-loop turn — the gap between exchanges is wire time lost.
    if (done)
        done(outcome);
    startNext();
}

void Session::deliverDeferred()
{
    auto [done, outcome] = std::move(m_deferred.front());
    m_deferred.pop_front();
    if (done)
        done(outcome);
}

QString outcomeStatusText(OutcomeStatus status)
{
    switch (status) {
    case OutcomeStatus::Ok: return Session::tr("ok");
    case OutcomeStatus::DeviceException: return Session::tr("refused by the device");
    case OutcomeStatus::Timeout: return Session::tr("no answer");
    case OutcomeStatus::LinkLost: return Session::tr("link lost");
    case OutcomeStatus::Cancelled: return Session::tr("cancelled");
    case OutcomeStatus::NotEncodable: return Session::tr("cannot be encoded");
    }
    return {};
}

} // namespace vt::model
