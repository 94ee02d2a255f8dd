// The editor's device actions over every online module of a ParameterDocument: Read all (each
// module's readable rows, or the rows a write or compare needs, in the fewest exchanges, with
// progress and cancel) and Write changes (model::WriteJob per module — range check, pacing, read
// back — one module after the other, with a per-parameter result list). The answers go into the
// device image (DeviceAccess), which the document reads. GUI thread; the DeviceAccess and the
// document must outlive the job.
#pragma once

#include "model/params/parameter_document.h"
#include "model/session/device_access.h"
#include "model/session/write_job.h"

#include <QObject>
#include <functional>
#include <memory>
#include <vector>

namespace vt::model {

class ReadAllJob : public QObject
{
    Q_OBJECT
public:
    ReadAllJob(DeviceAccess &access, ParameterDocument &document, QObject *parent = nullptr);
    ~ReadAllJob() override;

    // Which rows of a document module to read (default: every readable row); modules with none
    // are skipped.
    using RowsOf = std::function<std::vector<const dev::ParamMeta *>(int module)>;
    void setRows(RowsOf rows) { m_rowsOf = std::move(rows); }

    void start();
    void cancel();
    bool isRunning() const { return m_running; }
    // One line per module that did not read completely ("Module 2: 3 rows failed: no answer").
    const QStringList &problems() const { return m_problems; }
    // One line per value that arrived with a device warning (HART-7 manual §4.4.1 "Status"):
    // "Module 0: hart_DeviceSpecificStatus: status bytes mismatch … (14)". Not a problem: the
    // value was read.
    const QStringList &warnings() const { return m_warnings; }

signals:
    void progress(int done, int total); // exchanges over all modules
    void finished(bool complete);

private:
    void next();

    DeviceAccess &m_access;
    ParameterDocument &m_document;
    RowsOf m_rowsOf;
    std::vector<int> m_queue; // document module indexes still to read
    std::shared_ptr<DeviceAccess::ReadHandle> m_handle;
    QStringList m_problems;
    QStringList m_warnings;
    int m_doneBefore = 0; // exchanges of finished modules
    bool m_running = false;
    bool m_cancelled = false;
};

struct ModuleWriteResult
{
    int module = 0; // document module index
    std::vector<WriteItem> items;
};

class WriteChangesJob : public QObject
{
    Q_OBJECT
public:
    // `plan`: the rows to write per module (usually document.pendingWrites(i) for every online
    // module).
    WriteChangesJob(DeviceAccess &access, ParameterDocument &document,
                    std::vector<ModuleWriteResult> plan, QObject *parent = nullptr);
    ~WriteChangesJob() override;

    void start();
    void cancel();
    bool isRunning() const { return m_running; }
    const std::vector<ModuleWriteResult> &results() const { return m_results; }
    bool complete() const;

signals:
    void progress(int done, int total); // rows over all modules
    void itemChanged(int module, int index);
    void finished(bool complete);

private:
    void next();

    DeviceAccess &m_access;
    ParameterDocument &m_document;
    std::vector<ModuleWriteResult> m_results;
    std::size_t m_current = 0;
    WriteJob *m_job = nullptr; // child; the module being written
    int m_total = 0;
    int m_doneBefore = 0;
    bool m_running = false;
    bool m_cancelled = false;
};

} // namespace vt::model
