// FaultLink: wraps any Link and injects a seeded, reproducible schedule of faults (FaultSpec):
// dropped frames, one corrupted byte, delay, and a cut (the link goes Failed after N frames).
// A "frame" is one send() call going out or one received() chunk coming in. Each direction draws
// from its own std::mt19937 seeded from (seed, direction), and every frame consumes the same
// number of draws, so the same seed and traffic give the same faults, however tx and rx
// interleave. Owns the wrapped link; create and use it on one thread (the inner link's).
#pragma once

#include "transports/delay_line.h"
#include "transports/fault_spec.h"
#include "transports/link.h"

#include <memory>
#include <random>

namespace vt::link {

enum class FaultDirection { Tx, Rx };
enum class FaultKind { Drop, Corrupt, Delay, Cut };

struct FaultCounters
{
    quint64 txFrames = 0; // frames seen, injected or not
    quint64 rxFrames = 0;
    quint64 txDropped = 0;
    quint64 rxDropped = 0;
    quint64 txCorrupted = 0;
    quint64 rxCorrupted = 0;
    quint64 txDelayed = 0;
    quint64 rxDelayed = 0;
    bool cut = false;
};

class FaultLink : public Link
{
    Q_OBJECT
public:
    // Takes ownership of `inner` (it becomes a child).
    FaultLink(std::unique_ptr<Link> inner, const FaultSpec &spec, QObject *parent = nullptr);
    ~FaultLink() override;

    // Forwarded to the inner link; its states and failures are mirrored.
    void open() override;
    void close() override;
    void send(const QByteArray &bytes) override;
    void expectReply(qsizetype bytes) override { m_inner->expectReply(bytes); }
    bool reportsWireTime() const override { return m_inner->reportsWireTime(); }
    // "sim opat [fault drop=0.02,seed=7]"
    QString description() const override;

    Link &inner() const { return *m_inner; } // for inspection; drive the FaultLink instead
    const FaultSpec &spec() const { return m_spec; }
    // Re-seeds, re-arms the cut and resets the counters.
    void setSpec(const FaultSpec &spec);
    const FaultCounters &counters() const { return m_counters; }

signals:
    // For the telegram log: what was done to frame number `frameIndex` (0-based, both
    // directions counted together).
    void faultInjected(vt::link::FaultKind kind, vt::link::FaultDirection direction,
                       quint64 frameIndex);

private:
    struct Direction
    {
        Direction(FaultDirection d, DelayLine::Deliver deliver) : which(d), line(std::move(deliver))
        {
        }
        FaultDirection which;
        std::mt19937 rng;
        DelayLine line;
    };

    void onInnerState(LinkState state);
    void onInnerFailed(const QString &reason);
    void onInnerReceived(const QByteArray &bytes);
    // Applies the schedule to one frame; false when the frame is gone (dropped or cut).
    bool inject(Direction &dir, QByteArray &bytes, bool *delayed);
    void cut(FaultDirection direction, quint64 frameIndex);
    const FaultRates &rates(FaultDirection direction) const;
    void reseed();

    Link *m_inner; // child, deleted first in the destructor
    FaultSpec m_spec;
    Direction m_tx;
    Direction m_rx;
    FaultCounters m_counters;
    quint64 m_frameIndex = 0;
    bool m_cutting = false; // ignore the inner link's reaction to our own close()
};

} // namespace vt::link
