// PlcTestBench: what a PLC programmer does in the manuals' S7 examples, done from the PC — CMD 15
// sent cyclically over a node image link with per-module set values and a toggling TADR, each
// multiplexed answer decoded and filed under the module that gave it.
// Owner: the fold wizard or a test; GUI thread (the session's), which must outlive the bench.
#pragma once

#include "hcs/cmd15.h"
#include "hcs/profiles.h"
#include "hcs/types.h"
#include "model/session/session.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace vt::model {

// One module of the CMD 15 telegram: what the PC sends to it and what it last answered.
struct BenchModule
{
    std::uint8_t address = 0;                 // SADR: OPAT 0 = master, 1..7; DMA E22 1..5
    dev::hcs::ModuleSetpoints setpoints;      // DATx.1..3 of the request
    std::optional<dev::hcs::Profile> profile; // what VALUE1/VALUE2 and the bits mean
    std::optional<dev::hcs::CyclicResponse> last;
    quint64 answers = 0;
    std::vector<std::uint8_t> tadrs; // TADR of the recent answers (≤ 16), newest last
};

struct BenchCounters
{
    quint64 sent = 0;       // telegrams put on the wire
    quint64 answered = 0;   // decoded CMD 15 answers of one of our modules
    quint64 stale = 0;      // answers whose TADR was not the request's
    quint64 exceptions = 0; // error frames 0x8F
    quint64 failures = 0;   // no answer (timeout) or the link was lost
};

class PlcTestBench : public QObject
{
    Q_OBJECT
public:
    // `session` must run the node image protocol (see supports()); `modules`: how many modules the
    // telegram addresses (OPAT 1..8 with the master, DMA 1..5; DMA Profinet manual §4.1).
    PlcTestBench(Session &session, dev::hcs::Family family, std::size_t modules,
                 QObject *parent = nullptr);
    ~PlcTestBench() override;

    // The node image link is the only one carrying CMD 15 (ARCHITECTURE.md "Over TCP").
    static bool supports(const Session &session);
    // Empty when the family allows the module count, else why not.
    static QString checkModules(dev::hcs::Family family, std::size_t modules);

    dev::hcs::Family family() const { return m_family; }
    const std::vector<BenchModule> &modules() const { return m_modules; }
    const BenchCounters &counters() const { return m_counters; }
    std::uint8_t lastTadr() const { return m_tadr; }
    // The request bytes of the last cycle (the telegram, without image padding).
    const dev::Bytes &lastRequest() const { return m_lastRequest; }
    QString lastError() const { return m_lastError; }

    void setSetpoints(std::size_t index, const dev::hcs::ModuleSetpoints &setpoints);
    void setProfile(std::size_t index, std::optional<dev::hcs::Profile> profile);
    // Time between two telegrams (a telegram waits for the previous answer first). Default 50 ms.
    void setIntervalMs(int ms);
    int intervalMs() const { return m_intervalMs; }

    void start();
    void stop();
    bool isRunning() const { return m_running; }
    // One telegram now (also while stopped); false while one is still on the wire.
    bool sendOnce();

signals:
    void moduleAnswered(int index);
    void exceptionReceived(int code, const QString &text);
    void countersChanged();
    // The bench stopped by itself (the link was lost, the telegram cannot be built).
    void stopped(const QString &reason);

private:
    void cycle();
    void onOutcome(const Outcome &outcome, std::uint8_t tadr);
    std::optional<dev::Bytes> buildImage(std::uint8_t tadr);

    Session &m_session;
    dev::hcs::Family m_family;
    std::vector<BenchModule> m_modules;
    BenchCounters m_counters;
    QTimer m_timer;
    int m_intervalMs = 50;
    bool m_running = false;
    bool m_onWire = false;
    RequestId m_request = 0;
    std::uint8_t m_tadr = 0;
    dev::Bytes m_lastRequest;
    QString m_lastError;
};

} // namespace vt::model
