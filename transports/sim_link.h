// SimLink: the in-process link to a device simulator (STYLE.md rule 8: the simulator is just
// another link). send() feeds a vt::dev::ByteServer; what the server answers (its drain()) is
// delivered as received() from the event loop — never from inside send() — optionally after the
// time the bytes would spend on a serial wire (bytes × bits per character / baud), so timeouts
// and pacing behave as on a real line. Owned by the session; create and use it on one thread.
// The server is shared with whoever built it (the simulator front end) and is driven only here.
#pragma once

#include "transports/delay_line.h"
#include "transports/link.h"

#include <memory>

namespace vt::dev {
class ByteServer;
}

namespace vt::link {

class SimLink : public Link
{
    Q_OBJECT
public:
    SimLink(std::shared_ptr<dev::ByteServer> server, QString name, QObject *parent = nullptr);
    ~SimLink() override;

    // Opening → Open from the event loop (a simulator never refuses).
    void open() override;
    // Closed at once; answers still on the simulated wire are discarded.
    void close() override;
    void send(const QByteArray &bytes) override;
    // "sim opat"
    QString description() const override;

    // Simulated wire: 0 baud (the default) delivers on the next event-loop turn. Otherwise a
    // request occupies the master→device wire for its wire time, the answer starts after the
    // request has arrived and occupies the device→master wire for its own; each direction
    // carries one chunk at a time, like a UART. bitsPerCharacter: 10 for 8N1, 11 for 8E1/8O1.
    void setWireTiming(int baudRate, int bitsPerCharacter = 11);
    int baudRate() const { return m_baudRate; }
    int bitsPerCharacter() const { return m_bitsPerCharacter; }
    // Wire time of `bytes` bytes at the current timing (zero when untimed).
    std::chrono::nanoseconds wireTime(qsizetype bytes) const;

    // Collects output the server produced on its own (unsolicited frames, a cyclic node image)
    // and delivers it like an answer.
    void pump();

    dev::ByteServer &server() const { return *m_server; }

private:
    void collect(DelayLine::Clock::time_point requestArrives);

    std::shared_ptr<dev::ByteServer> m_server;
    QString m_name;
    int m_baudRate = 0;
    int m_bitsPerCharacter = 11;
    DelayLine m_toMaster;
    DelayLine::Clock::time_point m_requestWireFree{};
    DelayLine::Clock::time_point m_answerWireFree{};
    quint64 m_openToken = 0;
};

} // namespace vt::link
