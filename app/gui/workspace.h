// Workspace: what the main window works on — the parameter document, the connection to a node
// (built from a ConnectionSpec, its modules identified and attached to the document), the
// telegram log every frame goes to, and the slow poll that keeps the editor's d-block live.
// Qt Core only, so the GUI tests drive it without dialogs. GUI thread.
#pragma once

#include "model/params/parameter_document.h"
#include "model/session/actuator_ledger.h"
#include "model/session/connection.h"
#include "model/telegrams/telegram_log.h"

#include <QObject>
#include <memory>
#include <vector>

namespace vt::model {
class MonitorScheduler;
class TelegramRecorder;
} // namespace vt::model

namespace vt::app {

class Workspace : public QObject
{
    Q_OBJECT
public:
    explicit Workspace(const dev::DictionarySet &dictionaries, QObject *parent = nullptr);
    ~Workspace() override;

    const dev::DictionarySet &dictionaries() const { return m_dictionaries; }
    model::ParameterDocument &document() { return m_document; }
    // What is known to be on the node's modules; outlives each connection.
    model::DeviceImage &deviceImage() { return m_image; }
    // The actuator-moving values this tool changed on this connection (offered back on stop,
    // disconnect and quit).
    model::ActuatorLedger &actuatorLedger() { return m_ledger; }
    model::TelegramLog &telegramLog() { return m_log; }
    model::Connection *connection() const { return m_connection.get(); }
    const std::vector<model::ModuleInfo> &modules() const { return m_modules; }
    bool isConnected() const { return m_connection && m_ready; }

    // Builds and opens the connection, then identifies its modules (connected() or
    // connectFailed() follows). An existing connection is closed first.
    void connectTo(const model::ConnectionSpec &spec);
    void disconnectFromDevice();
    // Identifies every address the link can reach (Device ▸ Scan Node); modules found replace the
    // connection's module list. progress(done, total) while it runs, scanFinished() at the end.
    void scan();

    // The editor's live d-values: read-only display rows of every online module at `hz` (0 = off).
    void setLivePollRate(double hz);
    double livePollRate() const { return m_liveHz; }

signals:
    void connecting(const QString &description);
    // The connection is about to be destroyed: drop every pointer to it now.
    void aboutToDisconnect();
    void connected();
    void connectFailed(const QString &reason);
    void disconnected(const QString &reason); // empty when the user disconnected
    void scanProgress(int done, int total);
    void scanFinished(int found);

private:
    void identifyNext(std::vector<int> addresses, std::vector<model::ModuleInfo> found, int total,
                      bool scanning);
    void finishIdentify(std::vector<model::ModuleInfo> found, bool scanning);
    void teardown(bool notify = true);
    void updateLivePoll();

    const dev::DictionarySet &m_dictionaries;
    model::DeviceImage m_image;
    model::ActuatorLedger m_ledger{m_image};
    model::ParameterDocument m_document;
    model::TelegramLog m_log;
    std::unique_ptr<model::Connection> m_connection;
    std::unique_ptr<model::TelegramRecorder> m_recorder;
    std::unique_ptr<model::MonitorScheduler> m_live;
    std::vector<model::ModuleInfo> m_modules;
    double m_liveHz = 2.0;
    bool m_ready = false;
    quint64 m_generation = 0; // identify callbacks of an older connection are ignored
};

} // namespace vt::app
