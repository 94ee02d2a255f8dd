#include "sim_link.h"

#include "core/vt_assert.h"
#include "link_log.h"
#include "transports/byte_span.h"

#include <QTimer>
#include <algorithm>
#include <core/byte_server.h>
#include <span>

namespace vt::link {

SimLink::SimLink(std::shared_ptr<dev::ByteServer> server, QString name, QObject *parent)
    : Link(parent), m_server(std::move(server)), m_name(std::move(name)),
      m_toMaster([this](const QByteArray &bytes) {
          if (state() == LinkState::Open)
              emit received(bytes);
      })
{
    if (!m_server)
        qCWarning(lcLink).noquote() << description() << "was created without a simulator";
}

SimLink::~SimLink() = default;

QString SimLink::description() const
{
    return QStringLiteral("sim ") + m_name;
}

void SimLink::setWireTiming(int baudRate, int bitsPerCharacter)
{
    m_baudRate = std::max(0, baudRate);
    m_bitsPerCharacter = std::max(1, bitsPerCharacter);
}

std::chrono::nanoseconds SimLink::wireTime(qsizetype bytes) const
{
    if (m_baudRate <= 0 || bytes <= 0)
        return std::chrono::nanoseconds(0);
    const auto bits = static_cast<long long>(bytes) * m_bitsPerCharacter;
    return std::chrono::nanoseconds(bits * 1'000'000'000LL / m_baudRate);
}

void SimLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    setState(LinkState::Opening);
    const quint64 token = ++m_openToken;
    QTimer::singleShot(0, this, [this, token] {
        if (token != m_openToken || state() != LinkState::Opening)
            return;
        // Whoever makes a SimLink attaches its simulator; without one, fail like a link.
        VT_ASSERT(m_server, {
            setState(LinkState::Failed);
            emit failed(tr("No simulator is attached to %1").arg(description()));
            return;
        });
        m_requestWireFree = m_answerWireFree = DelayLine::Clock::now();
        setState(LinkState::Open);
    });
}

void SimLink::close()
{
    if (state() == LinkState::Closed)
        return;
    ++m_openToken;
    m_toMaster.clear();
    setState(LinkState::Closed);
}

void SimLink::send(const QByteArray &bytes)
{
    if (state() != LinkState::Open) {
        qCWarning(lcLink).noquote()
            << "send on" << description() << "while" << linkStateText(state()) << "- dropped"
            << bytes.size() << "bytes";
        return;
    }
    if (bytes.isEmpty())
        return;
    const auto now = DelayLine::Clock::now();
    const auto start = std::max(now, m_requestWireFree);
    m_requestWireFree = start + wireTime(bytes.size());
    // The server sees the request at once; only its answer is held back, which is all the
    // master can observe.
    m_server->receive(byteSpan(bytes));
    collect(m_requestWireFree);
}

void SimLink::pump()
{
    if (state() == LinkState::Open)
        collect(DelayLine::Clock::now());
}

void SimLink::collect(DelayLine::Clock::time_point requestArrives)
{
    const std::vector<std::uint8_t> answer = m_server->drain();
    if (answer.empty())
        return;
    QByteArray bytes = toByteArray(answer);
    const auto start = std::max(requestArrives, m_answerWireFree);
    m_answerWireFree = start + wireTime(bytes.size());
    m_toMaster.push(std::move(bytes), m_answerWireFree);
}

} // namespace vt::link
