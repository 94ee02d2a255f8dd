#include "fault_link.h"

#include "link_log.h"

namespace vt::link {

namespace {

// Uniform in [0, 1) from one raw draw. std::uniform_real_distribution is implementation-defined;
// this is not, so a seed means the same faults with every standard library.
double unit(std::uint32_t draw)
{
    return static_cast<double>(draw) / 4294967296.0;
}

} // namespace

FaultLink::FaultLink(std::unique_ptr<Link> inner, const FaultSpec &spec, QObject *parent)
    : Link(parent), m_inner(inner.release()), m_spec(spec),
      m_tx(FaultDirection::Tx,
           [this](const QByteArray &bytes) {
               if (m_inner->state() == LinkState::Open)
                   m_inner->send(bytes);
           }),
      m_rx(FaultDirection::Rx, [this](const QByteArray &bytes) {
          if (state() == LinkState::Open)
              emit received(bytes);
      })
{
    Q_ASSERT(m_inner);
    m_inner->setParent(this);
    reseed();
    connect(m_inner, &Link::stateChanged, this, &FaultLink::onInnerState);
    connect(m_inner, &Link::failed, this, &FaultLink::onInnerFailed);
    connect(m_inner, &Link::received, this, &FaultLink::onInnerReceived);
    connect(m_inner, &Link::lineQuiet, this, [this] {
        if (state() == LinkState::Open)
            emit lineQuiet();
    });
    connect(m_inner, &Link::frameOnWire, this, &Link::frameOnWire);
    setState(m_inner->state());
}

FaultLink::~FaultLink()
{
    m_inner->disconnect(this);
    delete m_inner;
}

QString FaultLink::description() const
{
    return m_inner->description() + QStringLiteral(" [fault ") + m_spec.toString() +
           QLatin1Char(']');
}

void FaultLink::setSpec(const FaultSpec &spec)
{
    m_spec = spec;
    reseed();
}

void FaultLink::reseed()
{
    std::seed_seq txSeed{m_spec.seed, 0u};
    std::seed_seq rxSeed{m_spec.seed, 1u};
    m_tx.rng.seed(txSeed);
    m_rx.rng.seed(rxSeed);
    m_counters = {};
    m_frameIndex = 0;
}

const FaultRates &FaultLink::rates(FaultDirection direction) const
{
    return direction == FaultDirection::Tx ? m_spec.tx : m_spec.rx;
}

void FaultLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    m_inner->open();
    setState(m_inner->state());
}

void FaultLink::close()
{
    m_tx.line.clear();
    m_rx.line.clear();
    m_inner->close();
    setState(LinkState::Closed);
}

void FaultLink::send(const QByteArray &bytes)
{
    if (state() != LinkState::Open) {
        qCWarning(lcLink).noquote()
            << "send on" << description() << "while" << linkStateText(state()) << "- dropped"
            << bytes.size() << "bytes";
        return;
    }
    QByteArray frame = bytes;
    bool delayed = false;
    if (!inject(m_tx, frame, &delayed))
        return;
    if (delayed)
        m_tx.line.push(frame,
                       DelayLine::Clock::now() + std::chrono::milliseconds(m_spec.tx.delayMs));
    else
        m_inner->send(frame);
}

void FaultLink::onInnerReceived(const QByteArray &bytes)
{
    if (state() != LinkState::Open)
        return;
    QByteArray frame = bytes;
    bool delayed = false;
    if (!inject(m_rx, frame, &delayed))
        return;
    if (delayed)
        m_rx.line.push(frame,
                       DelayLine::Clock::now() + std::chrono::milliseconds(m_spec.rx.delayMs));
    else
        emit received(frame);
}

bool FaultLink::inject(Direction &dir, QByteArray &bytes, bool *delayed)
{
    const quint64 index = m_frameIndex++;
    if (m_spec.cutAfterFrames && !m_counters.cut && index >= *m_spec.cutAfterFrames) {
        cut(dir.which, index);
        return false;
    }
    const bool tx = dir.which == FaultDirection::Tx;
    ++(tx ? m_counters.txFrames : m_counters.rxFrames);

    // Always four draws per frame, whatever happens to it.
    const std::uint32_t dropDraw = static_cast<std::uint32_t>(dir.rng());
    const std::uint32_t corruptDraw = static_cast<std::uint32_t>(dir.rng());
    const std::uint32_t positionDraw = static_cast<std::uint32_t>(dir.rng());
    const std::uint32_t flipDraw = static_cast<std::uint32_t>(dir.rng());

    const FaultRates &r = rates(dir.which);
    if (unit(dropDraw) < r.drop) {
        ++(tx ? m_counters.txDropped : m_counters.rxDropped);
        emit faultInjected(FaultKind::Drop, dir.which, index);
        return false;
    }
    if (!bytes.isEmpty() && unit(corruptDraw) < r.corrupt) {
        const auto size = static_cast<std::uint64_t>(bytes.size());
        const auto at = static_cast<qsizetype>(positionDraw % size);
        // 1..255: the byte always changes.
        const auto flip = static_cast<unsigned>(1 + flipDraw % 255);
        bytes[at] = static_cast<char>(static_cast<unsigned char>(bytes[at]) ^ flip);
        ++(tx ? m_counters.txCorrupted : m_counters.rxCorrupted);
        emit faultInjected(FaultKind::Corrupt, dir.which, index);
    }
    *delayed = r.delayMs > 0;
    if (*delayed) {
        ++(tx ? m_counters.txDelayed : m_counters.rxDelayed);
        emit faultInjected(FaultKind::Delay, dir.which, index);
    }
    return true;
}

void FaultLink::cut(FaultDirection direction, quint64 frameIndex)
{
    m_counters.cut = true;
    m_tx.line.clear();
    m_rx.line.clear();
    emit faultInjected(FaultKind::Cut, direction, frameIndex);
    m_cutting = true;
    m_inner->close();
    m_cutting = false;
    setState(LinkState::Failed);
    emit failed(tr("Fault injection cut the link after %1 frames").arg(frameIndex));
}

void FaultLink::onInnerState(LinkState innerState)
{
    if (m_cutting)
        return;
    if (innerState != LinkState::Open) {
        m_tx.line.clear();
        m_rx.line.clear();
    }
    setState(innerState);
}

void FaultLink::onInnerFailed(const QString &reason)
{
    if (m_cutting)
        return;
    m_tx.line.clear();
    m_rx.line.clear();
    setState(LinkState::Failed);
    emit failed(reason);
}

} // namespace vt::link
