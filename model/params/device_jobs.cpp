#include "device_jobs.h"

#include "model/text_language.h"

#include <QTimer>

namespace vt::model {

ReadAllJob::ReadAllJob(DeviceAccess &access, ParameterDocument &document, QObject *parent)
    : QObject(parent), m_access(access), m_document(document)
{
}

ReadAllJob::~ReadAllJob()
{
    if (m_handle)
        m_handle->cancel();
}

void ReadAllJob::start()
{
    m_queue.clear();
    m_problems.clear();
    m_warnings.clear();
    for (int i = 0; i < m_document.moduleCount(); ++i)
        if (m_document.module(i).online && (!m_rowsOf || !m_rowsOf(i).empty()))
            m_queue.push_back(i);
    m_running = true;
    m_cancelled = false;
    m_doneBefore = 0;
    next();
}

void ReadAllJob::cancel()
{
    m_cancelled = true;
    m_queue.clear();
    if (m_handle)
        m_handle->cancel();
}

void ReadAllJob::next()
{
    if (m_queue.empty() || m_cancelled) {
        m_running = false;
        m_handle.reset();
        // Deferred: the caller of start()/cancel() may still be on the stack.
        QTimer::singleShot(0, this,
                           [this] { emit finished(!m_cancelled && m_problems.isEmpty()); });
        return;
    }
    const int module = m_queue.front();
    m_queue.erase(m_queue.begin());
    const ParamModule &m = m_document.module(module);
    auto rows = m_rowsOf ? m_rowsOf(module) : readableRows(*m.dictionary, m.version, m.mode);
    const int address = m.address;
    auto lastTotal = std::make_shared<int>(0);
    m_handle = m_access.read(
        address, std::move(rows), Priority::User,
        [this, address, lastTotal](const ReadResult &result) {
            m_doneBefore += *lastTotal;
            std::size_t failedRows = 0;
            QString reason;
            for (const RowFailure &f : result.failures) {
                if (f.outcome.status == OutcomeStatus::NotEncodable)
                    continue; // rows this protocol cannot address (e.g. the HART field device
                              // status): not a failure of the read
                failedRows += f.rows.size();
                reason = f.outcome.reason;
            }
            if (failedRows > 0)
                m_problems << tr("Module %1: %n rows not read (%2)", nullptr,
                                 static_cast<int>(failedRows))
                                  .arg(address)
                                  .arg(reason);
            for (const RowValue &v : result.values)
                if (v.warningCode != 0 && v.row)
                    m_warnings << tr("Module %1: %2: %3 (%4)")
                                      .arg(address)
                                      .arg(QString::fromStdString(v.row->name),
                                           QString::fromStdString(v.warning.in(textLanguage())))
                                      .arg(v.warningCode);
            if (result.cancelled)
                m_cancelled = true;
            next();
        },
        [this, lastTotal](int done, int total) {
            *lastTotal = total;
            emit progress(m_doneBefore + done, m_doneBefore + total);
        });
}

WriteChangesJob::WriteChangesJob(DeviceAccess &access, ParameterDocument &document,
                                 std::vector<ModuleWriteResult> plan, QObject *parent)
    : QObject(parent), m_access(access), m_document(document), m_results(std::move(plan))
{
    for (const ModuleWriteResult &r : m_results)
        m_total += static_cast<int>(r.items.size());
}

WriteChangesJob::~WriteChangesJob() = default; // m_job is a child

void WriteChangesJob::start()
{
    m_running = true;
    m_cancelled = false;
    m_current = 0;
    m_doneBefore = 0;
    next();
}

void WriteChangesJob::cancel()
{
    m_cancelled = true;
    if (m_job)
        m_job->cancel();
}

bool WriteChangesJob::complete() const
{
    for (const ModuleWriteResult &r : m_results)
        for (const WriteItem &item : r.items)
            if (!isOnDevice(item.status))
                return false;
    return true;
}

void WriteChangesJob::next()
{
    while (m_current < m_results.size() && m_results[m_current].items.empty())
        ++m_current;
    if (m_current >= m_results.size() || m_cancelled) {
        m_running = false;
        QTimer::singleShot(0, this, [this] { emit finished(complete()); });
        return;
    }
    ModuleWriteResult &target = m_results[m_current];
    const ParamModule &m = m_document.module(target.module);
    m_job = new WriteJob(m_access, m.address, *m.dictionary, target.items, AuditOrigin::Editor,
                         WriteOptions{}, this);
    WriteJob *job = m_job;
    const int module = target.module;
    connect(job, &WriteJob::itemChanged, this, [this, job, module](int index) {
        m_results[m_current].items[static_cast<std::size_t>(index)] =
            job->items()[static_cast<std::size_t>(index)];
        emit itemChanged(module, index);
    });
    connect(job, &WriteJob::progress, this,
            [this](int done, int) { emit progress(m_doneBefore + done, m_total); });
    connect(job, &WriteJob::finished, this, [this, job, module](bool) {
        m_results[m_current].items = job->items();
        m_doneBefore += static_cast<int>(job->items().size());
        ++m_current;
        // The job is still on the stack: delete it from the event loop (or with this job).
        job->deleteLater();
        m_job = nullptr;
        next();
    });
    job->start();
}

} // namespace vt::model
