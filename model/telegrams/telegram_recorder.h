// TelegramRecorder: puts every frame a Session sends and receives, and every attempt that timed
// out, into a TelegramLog with the link and protocol it used. Owner: the GUI's Workspace (one per
// connection); same thread as the session and the log, which must both outlive it (it
// disconnects when either goes).
#pragma once

#include <QObject>
#include <QPointer>

namespace vt::model {

class Session;
class TelegramLog;

class TelegramRecorder : public QObject
{
    Q_OBJECT
public:
    TelegramRecorder(Session &session, TelegramLog &log, QObject *parent = nullptr);
};

} // namespace vt::model
