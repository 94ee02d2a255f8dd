#include "telegram_recorder.h"

#include "model/session/session.h"
#include "model/telegrams/telegram_log.h"
#include "transports/link.h"

namespace vt::model {

namespace {

TelegramRecord::Status statusOf(ReceivedKind kind)
{
    switch (kind) {
    case ReceivedKind::Answer: return TelegramRecord::Status::Ok;
    case ReceivedKind::Exception: return TelegramRecord::Status::DeviceException;
    case ReceivedKind::Unmatched:
    case ReceivedKind::Unsolicited: return TelegramRecord::Status::Unmatched;
    case ReceivedKind::Garbage: return TelegramRecord::Status::ChecksumError;
    }
    return TelegramRecord::Status::Malformed;
}

} // namespace

TelegramRecorder::TelegramRecorder(Session &session, TelegramLog &log, QObject *parent)
    : QObject(parent)
{
    QPointer<TelegramLog> target(&log);
    Session *s = &session;
    const auto protocol = [s] { return QString::fromLatin1(dev::key(s->adapter().protocol())); };
    connect(&session, &Session::frameSent, this,
            [s, target, protocol](const QByteArray &bytes, int module, qint64) {
                if (target)
                    target->append(dev::Direction::Request, s->link().description(), protocol(),
                                   module, bytes);
            });
    connect(&session, &Session::frameReceived, this,
            [s, target, protocol](const QByteArray &bytes, int module, qint64, ReceivedKind kind,
                                  const QString &note) {
                if (target)
                    target->append(dev::Direction::Response, s->link().description(), protocol(),
                                   module, bytes, statusOf(kind), note);
            });
    connect(&session, &Session::attemptTimedOut, this,
            [s, target, protocol](int module, int attempt, qint64) {
                if (target)
                    target->appendTimeout(
                        s->link().description(), protocol(), module,
                        TelegramRecorder::tr("no answer to attempt %1").arg(attempt));
            });
}

} // namespace vt::model
