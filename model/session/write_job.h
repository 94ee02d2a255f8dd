// WriteJob: the safe write — every value range-checked against the dictionary before
// anything is sent, only changed values, one at a time paced by the dictionary's write_pacing
// (DMA Profinet manual §3.4.1: ≥ 30 ms), each read back and compared. A job stopped by a lost
// link keeps a precise WriteRecord and resume() finishes it: rows whose write may have arrived
// are read first, so nothing is written twice blindly.
// Owner: the caller (GUI action, CLI command); same thread as the DeviceAccess, which must
// outlive it.
#pragma once

#include "model/audit/write_audit.h"
#include "model/session/device_access.h"
#include "model/session/write_record.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <functional>

namespace vt::model {

struct WriteOptions
{
    std::optional<int> pacingMs; // default: the dictionary's write_pacing
    bool verify = true;          // read each value back
    bool skipUnchanged = true;   // a row whose `before` equals its value is not sent
};

class WriteJob : public QObject
{
    Q_OBJECT
public:
    // Every item that ends (and every row it never sent) goes into the session log
    // (write_audit.h) under `origin`.
    WriteJob(DeviceAccess &access, int module, const dev::Dictionary &dictionary,
             std::vector<WriteItem> items, AuditOrigin origin, WriteOptions options = {},
             QObject *parent = nullptr);
    ~WriteJob() override;

    // Checks every row (RefusedLocally / Unchanged), then writes the rest in order.
    void start();
    // Takes up every row that needsResume(); Uncertain rows are read first.
    void resume();
    // Stops after the exchange on the wire; the rows not done stay NotSent.
    void cancel();

    bool isRunning() const { return m_running; }
    const std::vector<WriteItem> &items() const { return m_items; }
    int pacingMs() const { return m_pacingMs; }
    // Every row is on the device (Verified, Written or Unchanged).
    bool complete() const;

signals:
    void itemChanged(int index);
    void progress(int done, int total);
    // The job stopped: complete, cancelled, refused rows, or the link was lost (see items()).
    void finished(bool complete);

private:
    void run(); // works through m_order from the start
    void next();
    void writeItem(int index);
    // Reads item `index`'s row; `then` runs with the item unless the job died in the meantime.
    void readItem(int index, std::function<void(WriteItem &, const ReadResult &)> then);
    void verifyItem(int index);
    void probeItem(int index); // resume of an Uncertain row: read before writing
    void stopRemaining(const QString &reason);
    void settle(int index, WriteStatus status, const Sentence &reason = {},
                const dev::LocalText &deviceText = {});
    // A sentence of this class's tr() context, said when shown (write results stay on screen).
    static Sentence said(const char *source) { return {staticMetaObject.className(), source}; }
    void done();
    bool readBackEquals(const WriteItem &item, const dev::RawValue &value) const;

    DeviceAccess &m_access;
    int m_module;
    const dev::Dictionary &m_dictionary;
    std::vector<WriteItem> m_items;
    AuditOrigin m_origin;
    WriteOptions m_options;
    int m_pacingMs = 0;
    std::vector<int> m_order; // indexes still to do in this run
    std::size_t m_cursor = 0;
    bool m_running = false;
    bool m_cancelled = false;
    QElapsedTimer m_sinceWrite; // invalid until the first write of the job
    QTimer m_pace;
    int m_waiting = -1; // item waiting for the pacing timer
    int m_done = 0;
};

} // namespace vt::model
