#include "device_access.h"

#include "core/version.h"

#include <QTimer>
#include <algorithm>
#include <map>
#include <tuple>

namespace vt::model {

namespace {

constexpr std::uint16_t kDsp408Profile = 408;

struct IdentifyState
{
    dev::access::Identity identity;
    int remaining = 0;
    bool failed = false;
    Outcome failure;
};

struct ReadState
{
    std::vector<const dev::ParamMeta *> asked;
    std::map<const dev::ParamMeta *, dev::RawValue> got;
    std::map<const dev::ParamMeta *, std::pair<int, dev::LocalText>> warnings;
    std::vector<RowFailure> failures;
    bool cancelled = false; // an exchange ended Cancelled (the handle, the session's end)
    int done = 0;
    int total = 0;
    std::function<void(const ReadResult &)> finished;
    ReadProgress progress;
};

void merge(dev::access::Identity &into, const dev::access::Identity &from)
{
    if (from.versRaw >= 0)
        into.versRaw = from.versRaw;
    if (from.mode >= 0)
        into.mode = from.mode;
    if (from.manufacturer)
        into.manufacturer = from.manufacturer;
    if (from.expandedDeviceType)
        into.expandedDeviceType = from.expandedDeviceType;
    if (from.deviceId)
        into.deviceId = from.deviceId;
    if (from.capability)
        into.capability = from.capability;
    if (from.deviceProfile)
        into.deviceProfile = from.deviceProfile;
    if (!from.text.en.empty())
        into.text = into.text.en.empty()
                        ? from.text
                        : dev::LocalText{into.text.en + "; " + from.text.en,
                                         into.text.in(dev::Language::German) + "; " +
                                             from.text.in(dev::Language::German)};
}

} // namespace

DeviceAccess::DeviceAccess(Session &session, const dev::DictionarySet &dictionaries,
                           dev::HcsProduct product, QObject *parent)
    : QObject(parent), m_session(session), m_dictionaries(dictionaries), m_product(product)
{
    m_ownImage.beginConnection(); // its values are current while this access lives
}

DeviceAccess::~DeviceAccess() = default;

void DeviceAccess::identify(int module, std::function<void(const IdentifyResult &)> done)
{
    auto plan = m_session.adapter().planIdentify(module);
    auto state = std::make_shared<IdentifyState>();
    state->remaining = static_cast<int>(plan.size());
    auto conclude = [this, module, state, done = std::move(done)] {
        IdentifyResult result;
        result.module.address = module;
        if (state->failed) {
            result.failure = state->failure;
            result.message = state->failure.reason.isEmpty()
                                 ? outcomeStatusText(state->failure.status)
                                 : state->failure.reason;
            if (state->failure.status == OutcomeStatus::DeviceException)
                result.deviceText = state->failure.reply.exceptionText;
            done(result);
            return;
        }
        const dev::access::Identity &id = state->identity;
        // CiA 301 0x1000: profile 408 is the DSP-408 device profile (the ED1/SD1 over CANopen).
        const bool dsp408 = id.capability != 0 || id.deviceProfile == kDsp408Profile;
        if (id.manufacturer == 0 && !dsp408 && id.versRaw < 0) {
            result.message = tr("the module did not identify itself");
            done(result);
            return;
        }
        const dev::Result<dev::Identification, dev::LocalText> found =
            id.manufacturer != 0
                ? dev::identifyHart(m_dictionaries, id.manufacturer, id.expandedDeviceType)
            : dsp408 ? dev::identifyDsp408(m_dictionaries, id.capability)
                     : dev::identifyHcs(m_dictionaries, id.versRaw, id.mode, m_product);
        if (!found) {
            result.deviceText = found.error();
            done(result);
            return;
        }
        result.ok = true;
        result.module.identification = *found;
        result.module.dictionary = m_dictionaries.find(found->family);
        result.module.versRaw = id.versRaw;
        result.module.mode = id.mode;
        result.module.identityText = id.text;
        if (!found->exact)
            result.deviceText = found->warning;
        done(result);
    };
    if (plan.empty()) {
        QTimer::singleShot(0, this, conclude);
        return;
    }
    for (auto &t : plan) {
        m_session.submit(std::move(t), Priority::User, [state, conclude](const Outcome &outcome) {
            if (outcome.status == OutcomeStatus::Ok)
                merge(state->identity, outcome.reply.identity);
            else if (!state->failed) {
                state->failed = true;
                state->failure = outcome;
            }
            if (--state->remaining == 0)
                conclude();
        });
    }
}

std::shared_ptr<DeviceAccess::ReadHandle>
DeviceAccess::read(int module, std::vector<const dev::ParamMeta *> rows, Priority priority,
                   std::function<void(const ReadResult &)> done, ReadProgress progress)
{
    auto handle = std::make_shared<ReadHandle>();
    handle->m_session = &m_session;
    auto state = std::make_shared<ReadState>();
    state->asked = rows;
    state->finished = std::move(done);
    state->progress = std::move(progress);

    auto plan = m_session.adapter().planRead(module, rows);
    // Rows no exchange covers: not readable or not addressable on this protocol.
    std::vector<const dev::ParamMeta *> planned;
    for (const auto &t : plan)
        planned.insert(planned.end(), t.rows.begin(), t.rows.end());
    std::sort(planned.begin(), planned.end());
    std::vector<const dev::ParamMeta *> unplanned;
    for (const dev::ParamMeta *row : rows) {
        if (!std::binary_search(planned.begin(), planned.end(), row))
            unplanned.push_back(row);
    }
    if (!unplanned.empty()) {
        state->failures.push_back(RowFailure{
            std::move(unplanned),
            Outcome{OutcomeStatus::NotEncodable,
                    {},
                    0,
                    false,
                    tr("not readable over %1")
                        .arg(QString::fromLatin1(dev::key(m_session.adapter().protocol())))}});
    }
    state->total = static_cast<int>(plan.size());

    auto conclude = [state, handle] {
        handle->m_finished = true;
        ReadResult result;
        result.cancelled = handle->m_cancelled || state->cancelled;
        for (const dev::ParamMeta *row : state->asked) {
            auto it = state->got.find(row);
            if (it == state->got.end())
                continue;
            RowValue value{row, it->second, 0, {}};
            if (auto w = state->warnings.find(row); w != state->warnings.end())
                std::tie(value.warningCode, value.warning) = w->second;
            result.values.push_back(std::move(value));
        }
        result.failures = std::move(state->failures);
        if (state->finished)
            state->finished(result);
    };
    if (plan.empty()) {
        QTimer::singleShot(0, this, conclude);
        return handle;
    }
    QPointer<DeviceImage> image = &this->image();
    for (auto &t : plan) {
        auto rowsOfT = t.rows;
        handle->m_ids.push_back(m_session.submit(
            std::move(t), priority,
            [state, conclude, image, module, rowsOfT = std::move(rowsOfT)](const Outcome &outcome) {
                if (outcome.status == OutcomeStatus::Ok &&
                    outcome.reply.values.size() == rowsOfT.size()) {
                    std::vector<std::pair<const dev::ParamMeta *, dev::RawValue>> answered;
                    for (std::size_t i = 0; i < rowsOfT.size(); ++i) {
                        state->got[rowsOfT[i]] = outcome.reply.values[i];
                        if (outcome.reply.exceptionCode != 0)
                            state->warnings[rowsOfT[i]] = {outcome.reply.exceptionCode,
                                                           outcome.reply.exceptionText};
                        answered.emplace_back(rowsOfT[i], outcome.reply.values[i]);
                    }
                    if (image)
                        image->recordRead(module, answered);
                } else if (outcome.status == OutcomeStatus::Cancelled) {
                    state->cancelled = true;
                } else {
                    state->failures.push_back(RowFailure{rowsOfT, outcome});
                }
                // Which completion is the last is decided before the progress report: a
                // progress callback may run the event loop (a modal QProgressDialog's setValue()
                // does), and the completions still queued then arrive inside it.
                const bool last = ++state->done == state->total;
                if (state->progress)
                    state->progress(state->done, state->total);
                if (last)
                    conclude();
            }));
    }
    return handle;
}

RequestId DeviceAccess::write(int module, const dev::ParamMeta &row, const dev::RawValue &value,
                              Priority priority, std::optional<AuditOrigin> logAs, Completion done)
{
    QPointer<DeviceImage> image = &this->image();
    return m_session.submit(m_session.adapter().planWrite(module, row, value), priority,
                            [image, module, row = &row, value, logAs,
                             before = image->value(module, &row),
                             done = std::move(done)](const Outcome &outcome) {
                                if (logAs)
                                    auditExchange(module, row, before, value, outcome, *logAs);
                                if (outcome.status == OutcomeStatus::Ok && image)
                                    image->recordWritten(module, row, value);
                                if (done)
                                    done(outcome);
                            });
}

void DeviceAccess::ReadHandle::cancel()
{
    if (m_finished || m_cancelled)
        return;
    m_cancelled = true;
    for (RequestId id : m_ids)
        m_session->cancel(id);
}

std::vector<const dev::ParamMeta *>
readableRows(const dev::Dictionary &dictionary, const std::string &version, const std::string &mode)
{
    const std::string major = dev::majorVersion(version);
    std::vector<const dev::ParamMeta *> rows;
    for (const dev::ParamMeta &row : dictionary.params) {
        if (row.readable() && row.appliesTo(major, mode))
            rows.push_back(&row);
    }
    return rows;
}

QString identifyMessage(const IdentifyResult &result, dev::Language lang)
{
    if (!result.deviceText.en.empty())
        return QString::fromStdString(result.deviceText.in(lang));
    return result.message;
}

} // namespace vt::model
