// Session: the request queue between the model and one link. Transactions are queued by
// priority (user actions before monitor polls), sent one at a time (every protocol here is
// master/slave), matched by the protocol adapter, timed out from the wire speed, retried with
// back-off, cancellable. Every frame in and out is reported for the telegram log.
// Owner: whoever connects (app, CLI, tests); lives on the link's thread (the GUI thread) and is
// used only from there. The link is not owned and must outlive the session.
//
// Every completion runs exactly once, also when the session is destroyed with requests pending:
// ~Session() completes, before it returns and in this order, the completions already decided
// but not yet delivered (with their outcome), the request on the wire, then the queued ones
// (user before monitor), each with OutcomeStatus::Cancelled. Nothing is sent any more and no
// signal is emitted from the destructor. The contract for whoever submits: a completion runs
// inside ~Session(), so everything it touches must still be alive when the session is
// destroyed. An owner that holds its session destroys it before the members its completions
// use (declare the session last, or reset it first in the destructor); an object that may die
// before the session guards its completions (QPointer) — the session cannot know who is gone.
// A completion may submit() or cancel() during the destruction; what it submits is cancelled
// the same way.
#pragma once

#include "access/transaction.h"
#include "model/session/session_options.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <deque>
#include <functional>
#include <memory>
#include <utility>

namespace vt::link {
class Link;
enum class LinkState;
} // namespace vt::link

namespace vt::model {

enum class Priority { User = 0, Monitor = 1 };

enum class OutcomeStatus {
    Ok,              // the device answered: reply.values
    DeviceException, // the device refused: reply.exceptionCode / exceptionText
    Timeout,         // no valid answer after every retry
    LinkLost,        // the link failed or closed while the request was queued or on the wire
    Cancelled,
    NotEncodable, // the adapter cannot express the request (a programmer error or bad value)
};

struct Outcome
{
    OutcomeStatus status = OutcomeStatus::Ok;
    dev::access::Reply reply;
    int attempts = 0;
    bool sent = false; // at least one attempt left the master (a write may have arrived)
    QString reason;    // for people: what went wrong
};

using RequestId = quint64;

// What a received frame was to the request on the wire (for the telegram log's status).
enum class ReceivedKind { Answer, Exception, Unmatched, Garbage, Unsolicited };
using Completion = std::function<void(const Outcome &)>;

struct SessionCounters
{
    quint64 requests = 0; // completed, whatever the outcome
    quint64 attempts = 0; // frames sent
    quint64 retries = 0;
    quint64 timeouts = 0;   // attempts that got no answer in time
    quint64 exceptions = 0; // device refusals
    quint64 failures = 0;   // requests that ended Timeout / LinkLost
};

class Session : public QObject
{
    Q_OBJECT
public:
    Session(link::Link *link, std::unique_ptr<dev::access::ProtocolAdapter> adapter,
            SessionOptions options = {}, QObject *parent = nullptr);
    ~Session() override;

    // Queues `t`; `done` is called exactly once, never from inside submit() or cancel().
    RequestId submit(dev::access::Transaction t, Priority priority, Completion done);
    // The request ends Cancelled (if still queued) or its answer is ignored (if on the wire —
    // the wire exchange itself cannot be recalled).
    void cancel(RequestId id);
    void cancelAll(Priority priority);

    bool isBusy() const { return m_current != nullptr; }
    std::size_t queued() const { return m_user.size() + m_monitor.size(); }
    const SessionCounters &counters() const { return m_counters; }
    const SessionOptions &options() const { return m_options; }
    void setOptions(const SessionOptions &options) { m_options = options; }
    dev::access::ProtocolAdapter &adapter() const { return *m_adapter; }
    link::Link &link() const { return *m_link; }
    bool linkOpen() const;
    // Monotonic time since the session began, for timestamps of frames and samples.
    qint64 elapsedNs() const { return m_clock.nsecsElapsed(); }

signals:
    // A frame the session put on the wire / recognised coming back (for the telegram log).
    void frameSent(const QByteArray &bytes, int module, qint64 elapsedNs);
    void frameReceived(const QByteArray &bytes, int module, qint64 elapsedNs,
                       vt::model::ReceivedKind kind, const QString &note);
    // An attempt got no answer in time.
    void attemptTimedOut(int module, int attempt, qint64 elapsedNs);
    void countersChanged();
    // The queue ran empty.
    void idle();

private:
    struct Pending
    {
        RequestId id = 0;
        dev::access::Transaction transaction;
        Priority priority = Priority::User;
        Completion done;
        int attempts = 0;
        bool sent = false;
        bool cancelled = false;
    };

    void schedule();
    void startNext();
    void sendAttempt();
    // A cyclic exchange goes on within the attempt (ReplyStatus::Progress).
    void sendFollowUp();
    void onReceived(const QByteArray &bytes);
    void onTimeout();
    void onLinkState(link::LinkState state);
    void onLinkFailed(const QString &reason);
    void finish(std::unique_ptr<Pending> pending, Outcome outcome);
    void deliverDeferred();
    // The next request to end when the session is destroyed: on the wire, user, monitor.
    std::unique_ptr<Pending> takeAnyPending();
    void failEverything(OutcomeStatus status, const QString &reason);

    link::Link *m_link;
    std::unique_ptr<dev::access::ProtocolAdapter> m_adapter;
    SessionOptions m_options;
    std::deque<std::unique_ptr<Pending>> m_user;
    std::deque<std::unique_ptr<Pending>> m_monitor;
    std::unique_ptr<Pending> m_current;
    QTimer m_timeout;
    QTimer m_backoff;
    QTimer m_cycle;        // Progress: one bus cycle before the follow-up
    dev::Bytes m_followUp; // bytes the adapter asked to send next
    QElapsedTimer m_clock;
    QByteArray m_unmatched; // bytes of the current attempt not yet part of a recognised frame
    RequestId m_nextId = 1;
    SessionCounters m_counters;
    bool m_startScheduled = false;
    // Completions decided inside submit()/cancel()/a link failure, delivered from the event loop
    // (or by the destructor) in order.
    std::deque<std::pair<Completion, Outcome>> m_deferred;
    bool m_deliveryScheduled = false;
    bool m_destroying = false;
    int m_apiDepth = 0; // > 0 inside submit()/cancel()/failEverything(): completions are deferred
};

QString outcomeStatusText(OutcomeStatus status);

} // namespace vt::model
