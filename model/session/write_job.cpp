#include "write_job.h"

#include "core/vt_assert.h"
#include "dict/cooking.h"

#include <QPointer>
#include <algorithm>

namespace vt::model {

namespace {

// Each status's key (the CLI's JSON, logs) and its words for people (through tr()).
struct StatusWords
{
    WriteStatus status;
    const char *key;
    const char *text;
};
constexpr StatusWords kStatusWords[] = {
    {WriteStatus::Pending, "pending", QT_TRANSLATE_NOOP("vt::model::WriteJob", "pending")},
    {WriteStatus::Unchanged, "unchanged", QT_TRANSLATE_NOOP("vt::model::WriteJob", "unchanged")},
    {WriteStatus::RefusedLocally, "refused-locally",
     QT_TRANSLATE_NOOP("vt::model::WriteJob", "refused before sending")},
    {WriteStatus::Verified, "verified", QT_TRANSLATE_NOOP("vt::model::WriteJob", "verified")},
    {WriteStatus::Written, "written",
     QT_TRANSLATE_NOOP("vt::model::WriteJob", "written, not verified")},
    {WriteStatus::Refused, "refused",
     QT_TRANSLATE_NOOP("vt::model::WriteJob", "refused by the device")},
    {WriteStatus::Mismatch, "mismatch",
     QT_TRANSLATE_NOOP("vt::model::WriteJob", "read back differs")},
    {WriteStatus::Uncertain, "uncertain", QT_TRANSLATE_NOOP("vt::model::WriteJob", "uncertain")},
    {WriteStatus::NotSent, "not-sent", QT_TRANSLATE_NOOP("vt::model::WriteJob", "not sent")},
};

const StatusWords *wordsOf(WriteStatus status)
{
    for (const StatusWords &words : kStatusWords)
        if (words.status == status)
            return &words;
    assertFailed("every WriteStatus has words in kStatusWords", __FILE__, __LINE__);
    return nullptr;
}

QString valueText(const dev::ParamMeta &row, const dev::RawValue &value)
{
    if (dev::isText(value))
        return QStringLiteral("\"%1\"").arg(QString::fromStdString(std::get<std::string>(value)));
    return QString::fromStdString(
               dev::formatValue(row, dev::rawNumber(value), dev::Language::English)) +
           QStringLiteral(" (raw %1)").arg(dev::rawNumber(value), 0, 'g', 10);
}

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0'))
        s.pop_back();
    return s;
}

} // namespace

WriteJob::WriteJob(DeviceAccess &access, int module, const dev::Dictionary &dictionary,
                   std::vector<WriteItem> items, AuditOrigin origin, WriteOptions options,
                   QObject *parent)
    : QObject(parent), m_access(access), m_module(module), m_dictionary(dictionary),
      m_items(std::move(items)), m_origin(origin), m_options(options),
      m_pacingMs(options.pacingMs.value_or(dictionary.writePacingMs))
{
    m_pace.setSingleShot(true);
    m_pace.setTimerType(Qt::PreciseTimer);
    connect(&m_pace, &QTimer::timeout, this, [this] {
        const int index = m_waiting;
        m_waiting = -1;
        if (index >= 0)
            writeItem(index);
    });
}

WriteJob::~WriteJob() = default;

bool WriteJob::complete() const
{
    return std::all_of(m_items.begin(), m_items.end(),
                       [](const WriteItem &i) { return isOnDevice(i.status); });
}

void WriteJob::start()
{
    if (m_running)
        return;
    m_order.clear();
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        WriteItem &item = m_items[i];
        item.readBack.reset();
        item.exceptionCode = 0;
        item.reason = {};
        item.deviceText = {};
        item.status = WriteStatus::Pending;
        if (!item.row) {
            item.status = WriteStatus::RefusedLocally;
            item.reason = said(QT_TR_NOOP("unknown parameter"));
        } else if (dev::isText(item.value) != item.row->isString()) {
            item.status = WriteStatus::RefusedLocally;
            item.reason = (item.row->isString() ? said(QT_TR_NOOP("%1 expects text"))
                                                : said(QT_TR_NOOP("%1 expects a number")))
                              .arg(QString::fromStdString(item.row->name));
        } else if (!item.row->writable()) {
            item.status = WriteStatus::RefusedLocally;
            item.reason =
                said(QT_TR_NOOP("%1 is not writable")).arg(QString::fromStdString(item.row->name));
        } else if (!dev::isText(item.value)) {
            if (auto error = dev::checkWrite(*item.row, dev::rawNumber(item.value))) {
                item.status = WriteStatus::RefusedLocally;
                item.deviceText = error->message;
            }
        }
        if (item.status == WriteStatus::Pending && m_options.skipUnchanged && item.before &&
            readBackEquals(item, *item.before)) {
            item.status = WriteStatus::Unchanged;
        }
        if (item.status == WriteStatus::Pending) {
            m_order.push_back(static_cast<int>(i));
        } else {
            auditWrite(m_module, item, m_origin);
            emit itemChanged(static_cast<int>(i));
        }
    }
    run();
}

void WriteJob::resume()
{
    if (m_running)
        return;
    m_order.clear();
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        WriteItem &item = m_items[i];
        if (!needsResume(item.status))
            continue;
        if (item.status != WriteStatus::Uncertain)
            item.status = WriteStatus::Pending;
        m_order.push_back(static_cast<int>(i));
    }
    run();
}

void WriteJob::run()
{
    m_cursor = 0;
    m_done = 0;
    m_cancelled = false;
    m_running = true;
    emit progress(0, static_cast<int>(m_order.size()));
    QTimer::singleShot(0, this, &WriteJob::next);
}

void WriteJob::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    if (m_waiting >= 0) { // nothing on the wire: stop now
        m_pace.stop();
        m_waiting = -1;
        --m_cursor;
        stopRemaining(tr("cancelled"));
        done();
    }
}

void WriteJob::next()
{
    if (!m_running)
        return;
    if (m_cancelled) {
        stopRemaining(tr("cancelled"));
        done();
        return;
    }
    if (m_cursor >= m_order.size()) {
        done();
        return;
    }
    const int index = m_order[m_cursor++];
    if (m_items[static_cast<std::size_t>(index)].status == WriteStatus::Uncertain) {
        probeItem(index);
        return;
    }
    if (m_sinceWrite.isValid() && m_sinceWrite.elapsed() < m_pacingMs) {
        m_waiting = index;
        m_pace.start(static_cast<int>(m_pacingMs - m_sinceWrite.elapsed()));
        return;
    }
    writeItem(index);
}

void WriteJob::writeItem(int index)
{
    WriteItem &item = m_items[static_cast<std::size_t>(index)];
    m_access.write( // the session log gets the item when it settles, with its read back
        m_module, *item.row, item.value, Priority::User, std::nullopt,
        [this, guard = QPointer<WriteJob>(this), index](const Outcome &outcome) {
            if (!guard)
                return; // the job was destroyed while its request was out
            m_sinceWrite
                .start(); // pacing counts from the device's acknowledgement (or the give-up)
            WriteItem &it = m_items[static_cast<std::size_t>(index)];
            switch (outcome.status) {
            case OutcomeStatus::Ok:
                if (m_options.verify && it.row->readable()) {
                    verifyItem(index);
                    return;
                }
                settle(index, WriteStatus::Written,
                       said(QT_TR_NOOP("acknowledged; not read back")));
                next();
                return;
            case OutcomeStatus::DeviceException:
                it.exceptionCode = outcome.reply.exceptionCode;
                settle(index, WriteStatus::Refused, {}, outcome.reply.exceptionText);
                next();
                return;
            case OutcomeStatus::NotEncodable:
                settle(index, WriteStatus::RefusedLocally, Sentence::verbatim(outcome.reason));
                next();
                return;
            case OutcomeStatus::Timeout:
            case OutcomeStatus::LinkLost:
            case OutcomeStatus::Cancelled:
                settle(index, outcome.sent ? WriteStatus::Uncertain : WriteStatus::NotSent,
                       outcome.sent ? said(QT_TR_NOOP("sent, but no answer (%1): the value may or "
                                                      "may not be on the device"))
                                          .arg(outcome.reason)
                                    : Sentence::verbatim(outcome.reason));
                stopRemaining(outcome.reason);
                done();
                return;
            }
        });
}

void WriteJob::readItem(int index, std::function<void(WriteItem &, const ReadResult &)> then)
{
    m_access.read(m_module, {m_items[static_cast<std::size_t>(index)].row}, Priority::User,
                  [this, guard = QPointer<WriteJob>(this), index,
                   then = std::move(then)](const ReadResult &result) {
                      if (!guard)
                          return; // the job was destroyed while its request was out
                      then(m_items[static_cast<std::size_t>(index)], result);
                  });
}

void WriteJob::verifyItem(int index)
{
    readItem(index, [this, index](WriteItem &it, const ReadResult &result) {
        if (result.values.size() == 1) {
            it.readBack = result.values.front().value;
            if (readBackEquals(it, *it.readBack))
                settle(index, WriteStatus::Verified);
            else
                settle(index, WriteStatus::Mismatch,
                       said(QT_TR_NOOP("read back %1, expected %2"))
                           .arg(valueText(*it.row, *it.readBack))
                           .arg(valueText(*it.row, it.value)));
            next();
            return;
        }
        Outcome outcome = result.failures.empty() ? Outcome{} : result.failures.front().outcome;
        if (result.cancelled && result.failures.empty()) // e.g. the session ended
            outcome = Outcome{OutcomeStatus::Cancelled,
                              {},
                              0,
                              false,
                              outcomeStatusText(OutcomeStatus::Cancelled)};
        settle(index, WriteStatus::Written,
               said(QT_TR_NOOP("acknowledged; the read back failed (%1)")).arg(outcome.reason));
        if (outcome.status == OutcomeStatus::LinkLost || outcome.status == OutcomeStatus::Timeout ||
            outcome.status == OutcomeStatus::Cancelled) {
            stopRemaining(outcome.reason);
            done();
            return;
        }
        next();
    });
}

void WriteJob::probeItem(int index)
{
    readItem(index, [this, index](WriteItem &it, const ReadResult &result) {
        if (result.values.size() == 1 && readBackEquals(it, result.values.front().value)) {
            it.readBack = result.values.front().value;
            settle(index, WriteStatus::Verified,
                   said(QT_TR_NOOP("found on the device after the interruption")));
            next();
            return;
        }
        if (result.values.size() == 1) { // not there: write it now, paced like any write
            it.status = WriteStatus::Pending;
            --m_cursor;
            next();
            return;
        }
        Outcome outcome = result.failures.empty() ? Outcome{} : result.failures.front().outcome;
        if (result.cancelled && result.failures.empty()) // e.g. the session ended
            outcome = Outcome{OutcomeStatus::Cancelled,
                              {},
                              0,
                              false,
                              outcomeStatusText(OutcomeStatus::Cancelled)};
        stopRemaining(outcome.reason); // it stays Uncertain
        done();
    });
}

void WriteJob::settle(int index, WriteStatus status, const Sentence &reason,
                      const dev::LocalText &deviceText)
{
    WriteItem &item = m_items[static_cast<std::size_t>(index)];
    item.status = status;
    item.reason = reason;
    item.deviceText = deviceText;
    auditWrite(m_module, item, m_origin);
    ++m_done;
    emit itemChanged(index);
    emit progress(m_done, static_cast<int>(m_order.size()));
}

void WriteJob::stopRemaining(const QString &reason)
{
    for (std::size_t k = m_cursor; k < m_order.size(); ++k) {
        WriteItem &item = m_items[static_cast<std::size_t>(m_order[k])];
        if (item.status == WriteStatus::Pending) {
            item.status = WriteStatus::NotSent;
            item.reason = said(QT_TR_NOOP("not sent: the write stopped (%1)")).arg(reason);
            item.deviceText = {};
            auditWrite(m_module, item, m_origin);
            emit itemChanged(m_order[k]);
        }
    }
    m_cursor = m_order.size();
}

void WriteJob::done()
{
    if (!m_running)
        return;
    m_running = false;
    emit finished(complete());
}

bool WriteJob::readBackEquals(const WriteItem &item, const dev::RawValue &value) const
{
    if (dev::isText(item.value) || dev::isText(value)) {
        if (!dev::isText(item.value) || !dev::isText(value))
            return false;
        return trimmed(std::get<std::string>(item.value)) == trimmed(std::get<std::string>(value));
    }
    if (item.row && item.row->isFloat())
        return static_cast<float>(dev::rawNumber(item.value)) ==
               static_cast<float>(dev::rawNumber(value));
    return dev::rawNumber(item.value) == dev::rawNumber(value);
}

Sentence writeStatusSentence(WriteStatus status)
{
    const StatusWords *words = wordsOf(status);
    return words ? Sentence("vt::model::WriteJob", words->text) : Sentence();
}

QString writeStatusText(WriteStatus status)
{
    return writeStatusSentence(status).text();
}

Sentence writeReason(const WriteItem &item)
{
    if (!item.deviceText.en.empty())
        return Sentence::bilingual(item.deviceText);
    return item.reason;
}

QString writeReasonText(const WriteItem &item, dev::Language lang)
{
    if (!item.deviceText.en.empty())
        return QString::fromStdString(item.deviceText.in(lang));
    return item.reason.text();
}

const char *writeStatusKey(WriteStatus status)
{
    const StatusWords *words = wordsOf(status);
    return words ? words->key : "?";
}

} // namespace vt::model
