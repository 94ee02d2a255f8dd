#include "workspace.h"

#include "model/monitor/monitor_scheduler.h"
#include "model/telegrams/telegram_recorder.h"

#include <QSignalBlocker>

namespace vt::app {

Workspace::Workspace(const dev::DictionarySet &dictionaries, QObject *parent)
    : QObject(parent), m_dictionaries(dictionaries)
{
    m_document.setDeviceImage(&m_image);
}

// Silent: whoever listens may already be half destroyed (the main window closes the connection
// itself before that).
Workspace::~Workspace()
{
    teardown(false);
}

void Workspace::teardown(bool notify)
{
    ++m_generation;
    m_ready = false;
    if (m_connection && notify)
        emit aboutToDisconnect();
    m_live.reset();
    m_recorder.reset();
    {
        const QSignalBlocker silent(notify ? nullptr : &m_image);
        m_image.endConnection();
    }
    if (m_connection) {
        m_connection->disconnect(this);
        m_connection->close();
        m_connection.reset();
    }
    m_modules.clear();
}

void Workspace::connectTo(const model::ConnectionSpec &spec)
{
    if (m_connection)
        disconnectFromDevice();
    auto made = model::Connection::create(spec, m_dictionaries);
    if (!made.ok()) {
        emit connectFailed(made.error());
        return;
    }
    m_connection = std::move(made).value();
    m_connection->access().useImage(m_image);
    m_image.beginConnection();
    m_ledger.clear();
    m_recorder = std::make_unique<model::TelegramRecorder>(m_connection->session(), m_log);
    const quint64 generation = ++m_generation;
    connect(m_connection.get(), &model::Connection::opened, this, [this, generation] {
        if (generation != m_generation)
            return;
        const std::vector<int> addresses = m_connection->moduleAddresses();
        identifyNext(addresses, {}, static_cast<int>(addresses.size()), false);
    });
    connect(m_connection.get(), &model::Connection::failed, this, [this](const QString &reason) {
        teardown();
        emit connectFailed(reason);
    });
    connect(m_connection.get(), &model::Connection::lost, this, [this](const QString &reason) {
        m_document.detachDevice();
        teardown();
        emit disconnected(reason);
    });
    emit connecting(m_connection->displayText());
    m_connection->open();
}

void Workspace::disconnectFromDevice()
{
    if (!m_connection)
        return;
    m_document.detachDevice();
    teardown();
    emit disconnected(QString());
}

void Workspace::scan()
{
    if (!m_connection || !m_ready)
        return;
    const std::vector<int> addresses = m_connection->scanAddresses();
    identifyNext(addresses, {}, static_cast<int>(addresses.size()), true);
}

void Workspace::identifyNext(std::vector<int> addresses, std::vector<model::ModuleInfo> found,
                             int total, bool scanning)
{
    if (scanning)
        emit scanProgress(total - static_cast<int>(addresses.size()), total);
    if (addresses.empty()) {
        finishIdentify(std::move(found), scanning);
        return;
    }
    const int address = addresses.front();
    addresses.erase(addresses.begin());
    const quint64 generation = m_generation;
    m_connection->access().identify(
        address, [this, generation, addresses = std::move(addresses), found = std::move(found),
                  total, scanning](const model::IdentifyResult &result) mutable {
            if (generation != m_generation)
                return;
            if (result.ok)
                found.push_back(result.module);
            // Next from the event loop: the session is still inside this completion.
            QMetaObject::invokeMethod(
                this,
                [this, generation, addresses = std::move(addresses), found = std::move(found),
                 total, scanning]() mutable {
                    if (generation == m_generation)
                        identifyNext(std::move(addresses), std::move(found), total, scanning);
                },
                Qt::QueuedConnection);
        });
}

void Workspace::finishIdentify(std::vector<model::ModuleInfo> found, bool scanning)
{
    if (!scanning && found.empty()) {
        const QString reason = tr("No module answered on %1.").arg(m_connection->displayText());
        teardown();
        emit connectFailed(reason);
        return;
    }
    m_modules = std::move(found);
    m_document.attachDevice(m_modules);
    m_ready = true;
    updateLivePoll();
    if (scanning)
        emit scanFinished(static_cast<int>(m_modules.size()));
    else
        emit connected();
}

void Workspace::setLivePollRate(double hz)
{
    m_liveHz = hz;
    updateLivePoll();
}

void Workspace::updateLivePoll()
{
    m_live.reset();
    if (!isConnected() || m_liveHz <= 0)
        return;
    m_live = std::make_unique<model::MonitorScheduler>(m_connection->access());
    for (const model::ModuleInfo &info : m_modules) {
        std::vector<const dev::ParamMeta *> rows;
        const int index = m_document.findModule(info.address);
        if (index < 0)
            continue;
        const model::ParamModule &m = m_document.module(index);
        // The ED1/SD1's live values sit in its function blocks too (dpc_ActualVal,
        // dpc_CtrlDeviationVal, ED1/SD1 manual §4.8.30, §4.8.31), not only in "db".
        const bool dsp408 = info.dictionary->protocol == dev::DeviceProtocol::Dsp408;
        for (const dev::ParamMeta *row : model::readableRows(*info.dictionary, m.version, m.mode))
            if (!row->writable() && (row->block == "d" || row->block == "db" ||
                                     (dsp408 && row->kind == dev::RowKind::Live)))
                rows.push_back(row);
        if (!rows.empty())
            m_live->setModule(info.address, std::move(rows), m_liveHz);
    }
    // The samples reach the document through the device image (DeviceAccess records them).
    m_live->start();
}

} // namespace vt::app
