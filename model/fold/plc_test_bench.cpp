#include "model/fold/plc_test_bench.h"

#include "access/node_image_adapter.h"
#include "hcs/exceptions.h"
#include "model/text_language.h"

#include <QPointer>
#include <algorithm>

namespace vt::model {

namespace {

constexpr std::size_t kTadrHistory = 16;

const dev::access::NodeImageAdapter *nodeImageOf(const Session &session)
{
    return dynamic_cast<const dev::access::NodeImageAdapter *>(&session.adapter());
}

} // namespace

PlcTestBench::PlcTestBench(Session &session, dev::hcs::Family family, std::size_t modules,
                           QObject *parent)
    : QObject(parent), m_session(session), m_family(family)
{
    const std::size_t count = std::min(modules, dev::hcs::maxCyclicModules(family));
    for (std::size_t i = 0; i < count; ++i) {
        BenchModule module;
        module.address = dev::hcs::moduleAddress(family, i);
        m_modules.push_back(module);
    }
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &PlcTestBench::cycle);
}

PlcTestBench::~PlcTestBench()
{
    if (m_onWire)
        m_session.cancel(m_request);
}

bool PlcTestBench::supports(const Session &session)
{
    return nodeImageOf(session) != nullptr;
}

QString PlcTestBench::checkModules(dev::hcs::Family family, std::size_t modules)
{
    if (dev::hcs::snumForModules(family, modules))
        return {};
    // OPAT manual §3.1: master + up to 7 slaves; DMA Profinet manual §4.1: up to 5 modules.
    return tr("CMD 15 addresses 1 to %1 modules on this node, not %2.")
        .arg(dev::hcs::maxCyclicModules(family))
        .arg(modules);
}

void PlcTestBench::setSetpoints(std::size_t index, const dev::hcs::ModuleSetpoints &setpoints)
{
    if (index < m_modules.size())
        m_modules[index].setpoints = setpoints;
}

void PlcTestBench::setProfile(std::size_t index, std::optional<dev::hcs::Profile> profile)
{
    if (index < m_modules.size())
        m_modules[index].profile = profile;
}

void PlcTestBench::setIntervalMs(int ms)
{
    m_intervalMs = std::max(ms, 1);
}

void PlcTestBench::start()
{
    if (m_running)
        return;
    m_running = true;
    cycle();
}

void PlcTestBench::stop()
{
    m_running = false;
    m_timer.stop();
}

bool PlcTestBench::sendOnce()
{
    if (m_onWire)
        return false;
    const bool wasRunning = m_running;
    m_running = false; // one telegram, no follow-up
    cycle();
    m_running = wasRunning;
    return m_onWire;
}

std::optional<dev::Bytes> PlcTestBench::buildImage(std::uint8_t tadr)
{
    dev::hcs::CyclicRequest request;
    request.tadr = tadr;
    for (const BenchModule &module : m_modules)
        request.modules.push_back(module.setpoints);
    auto encoded = dev::hcs::encode(request, m_family);
    if (!encoded.ok())
        return std::nullopt;
    dev::Bytes image = std::move(encoded).value();
    m_lastRequest = image;
    const auto *adapter = nodeImageOf(m_session);
    // DMA Profibus Anleitung §5.1 / OPAT manual §3.1: a telegram longer than the GSD module's
    // output image gets exception 9; say so here instead of sending a cut telegram.
    if (!adapter || image.size() > adapter->layout().outputBytes)
        return std::nullopt;
    image.resize(adapter->layout().outputBytes, 0);
    return image;
}

void PlcTestBench::cycle()
{
    if (m_onWire)
        return;
    if (!supports(m_session) || !checkModules(m_family, m_modules.size()).isEmpty()) {
        m_lastError = supports(m_session) ? checkModules(m_family, m_modules.size())
                                          : tr("The PLC test bench needs a node image link.");
        stop();
        emit stopped(m_lastError);
        return;
    }
    // OPAT manual §1.5 / DMA Profinet manual §1.4: the node answers only a changed telegram, so
    // every cycle carries the next TADR (never 0, which a zeroed image also has).
    const auto tadr = static_cast<std::uint8_t>(m_tadr == 0xFF ? 1 : m_tadr + 1);
    const auto image = buildImage(tadr);
    if (!image) {
        m_lastError = tr("The CMD 15 telegram for %1 modules does not fit the node's output image.")
                          .arg(m_modules.size());
        stop();
        emit stopped(m_lastError);
        return;
    }
    m_tadr = tadr;
    auto t = dev::access::Transaction::rawFrame(m_modules.empty() ? 0 : m_modules.front().address,
                                                *image);
    m_onWire = true;
    ++m_counters.sent;
    QPointer<PlcTestBench> self(this);
    m_request =
        m_session.submit(std::move(t), Priority::User, [self, tadr](const Outcome &outcome) {
            if (self)
                self->onOutcome(outcome, tadr);
        });
    emit countersChanged();
}

void PlcTestBench::onOutcome(const Outcome &outcome, std::uint8_t tadr)
{
    m_onWire = false;
    bool linkLost = false;
    if (outcome.status != OutcomeStatus::Ok) {
        ++m_counters.failures;
        m_lastError = outcome.reason.isEmpty() ? outcomeStatusText(outcome.status) : outcome.reason;
        linkLost = outcome.status == OutcomeStatus::LinkLost;
    } else {
        const auto decoded = dev::hcs::decodeCyclicResponse(
            outcome.reply.frame, dev::hcs::DecodeOptions{m_family, true});
        if (!decoded.ok()) {
            const dev::DecodeError &error = decoded.error();
            if (error.code == dev::DecodeErrc::DeviceException) {
                ++m_counters.exceptions;
                m_lastError = localText(dev::hcs::exceptionTextOrUnknown(
                    m_family, dev::hcs::kCmdCyclic, error.deviceCode));
                emit exceptionReceived(error.deviceCode, m_lastError);
            } else {
                ++m_counters.stale; // a CMD 3/6 answer or other frame, not ours
            }
        } else if (decoded->tadr != tadr) {
            ++m_counters.stale;
        } else {
            const auto it =
                std::find_if(m_modules.begin(), m_modules.end(),
                             [&](const BenchModule &m) { return m.address == decoded->sadr; });
            if (it == m_modules.end()) {
                ++m_counters.stale;
            } else {
                it->last = *decoded;
                ++it->answers;
                it->tadrs.push_back(decoded->tadr);
                if (it->tadrs.size() > kTadrHistory)
                    it->tadrs.erase(it->tadrs.begin());
                ++m_counters.answered;
                emit moduleAnswered(static_cast<int>(it - m_modules.begin()));
            }
        }
    }
    emit countersChanged();
    if (linkLost) {
        stop();
        emit stopped(m_lastError);
        return;
    }
    if (m_running)
        m_timer.start(m_intervalMs);
}

} // namespace vt::model
