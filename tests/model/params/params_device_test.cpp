// The editor's device round trip at model level against the built-in simulator:
// connect → read all → edit C1.07 to 1.000 V → write → the simulator holds raw 1000 → save →
// reopen → compare with the device shows no difference; undo after the write differs again.
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "model/params/compare_model.h"
#include "model/params/device_jobs.h"
#include "model/params/param_file_io.h"
#include "model/params/parameter_tree_model.h"
#include "model/session/connection.h"
#include "sim_rig.h"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <algorithm>

namespace vt::test {
namespace {

bool readAll(model::Connection &connection, model::ParameterDocument &doc)
{
    model::ReadAllJob job(connection.access(), doc);
    QSignalSpy finished(&job, &model::ReadAllJob::finished);
    job.start();
    return finished.wait(kWaitMs) && finished.at(0).at(0).toBool();
}

TEST(ParamsDevice, ReadEditWriteSaveReopenCompare)
{
    QTemporaryDir logDir;
    model::AuditLog audit(QStringLiteral("valvetune"), QStringLiteral("test"), logDir.path());
    const model::AuditLog::Scope auditScope(audit);
    auto c = connectSim("dma-pn-v51");
    ASSERT_TRUE(c);
    ASSERT_EQ(c->modules.size(), 1u);
    model::ParameterDocument doc;
    model::ParameterTreeModel tree(doc);
    doc.setDeviceImage(&c->access().image());
    doc.attachDevice(c->modules);
    ASSERT_TRUE(readAll(*c->connection, doc));
    const dev::Dictionary &dict = *c->modules[0].dictionary;
    const dev::ParamMeta *c107 = dict.find("C1.07");
    ASSERT_TRUE(doc.value(0, c107, model::Layer::Device));

    const QModelIndex value = tree.indexOf(0, c107, model::ParameterTreeModel::ColValue);
    ASSERT_TRUE(tree.setData(value, QStringLiteral("1.000 V")));
    EXPECT_TRUE(doc.differsFromDevice(0, c107));
    std::vector<model::ModuleWriteResult> plan{{0, doc.pendingWrites(0)}};
    ASSERT_EQ(plan[0].items.size(), 1u);
    model::WriteChangesJob write(c->connection->access(), doc, plan);
    QSignalSpy written(&write, &model::WriteChangesJob::finished);
    write.start();
    ASSERT_TRUE(written.wait(kWaitMs));
    EXPECT_TRUE(written.at(0).at(0).toBool());
    EXPECT_EQ(write.results()[0].items[0].status, model::WriteStatus::Verified);
    EXPECT_EQ(storedRaw(c->simModule(0), *c107), 1000.0);
    EXPECT_FALSE(doc.differsFromDevice(0, c107));
    // The session log has the write, verified, under the editor.
    const model::AuditLogContents log = model::readAuditLog(audit.path());
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    ASSERT_EQ(log.entries.size(), 1u);
    EXPECT_EQ(log.entries[0].row, QStringLiteral("C1.07"));
    EXPECT_EQ(log.entries[0].oldText, QStringLiteral("0.000 V"));
    EXPECT_EQ(log.entries[0].newText, QStringLiteral("1.000 V"));
    EXPECT_EQ(log.entries[0].status, QStringLiteral("verified"));
    EXPECT_EQ(log.entries[0].origin, QStringLiteral("editor"));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("press.vtpar"));
    ASSERT_FALSE(model::saveParamFile(path, doc.toParamFile("ValveTune test"), dictionaries(),
                                      dev::Language::English));
    doc.markSaved(path);

    auto reread = model::readParamFile(path, dev::Language::English);
    ASSERT_TRUE(reread.ok()) << reread.error().toStdString();
    model::ParameterDocument reopened;
    reopened.loadFile(*reread, dictionaries(), path);
    reopened.setDeviceImage(&c->access().image());
    reopened.attachDevice(c->modules);
    ASSERT_TRUE(readAll(*c->connection, reopened));
    EXPECT_EQ(reopened.value(0, c107), dev::RawValue{1000.0});
    model::CompareModel compare(reopened);
    compare.compareWithDevice();
    EXPECT_EQ(compare.rowCount(), 0);

    // Undo after the write: the editor goes back to the old value, the device keeps the new one.
    doc.undoStack()->undo();
    EXPECT_TRUE(doc.differsFromDevice(0, c107));
    EXPECT_TRUE(tree.indexOf(0, c107).data(model::DiffersFromDeviceRole).toBool());
}

// A shown window-modal QProgressDialog runs the event loop in setValue() after posting its
// repaint: the Read All job's progress handler may do so inside the completion that reports it,
// and the exchanges still queued (here: all of them, cancelled at once) then complete inside it.
// The job still finishes once.
TEST(ParamsDevice, ReadAllFinishesOnceWhenItsProgressHandlerRunsTheEventLoop)
{
    auto c = connectSim("dma-pn-v51");
    ASSERT_TRUE(c);
    model::ParameterDocument doc;
    doc.setDeviceImage(&c->access().image());
    doc.attachDevice(c->modules);
    model::ReadAllJob job(c->access(), doc);
    int depth = 0;
    int nested = 0;
    QObject::connect(&job, &model::ReadAllJob::progress, &job, [&] {
        nested = std::max(nested, depth);
        ++depth;
        // Something posted, as the dialog's repaint: only then does the nested loop dispatch the
        // events posted before it.
        QMetaObject::invokeMethod(
            &job, [] {}, Qt::QueuedConnection);
        QCoreApplication::processEvents();
        --depth;
    });
    QSignalSpy finished(&job, &model::ReadAllJob::finished);
    job.start();
    job.cancel();
    ASSERT_TRUE(finished.wait(kWaitMs));
    spinFor(50);          // the window of a second finished()
    EXPECT_GT(nested, 0); // the test ran completions inside a progress report
    EXPECT_EQ(finished.count(), 1);
    EXPECT_FALSE(finished.at(0).at(0).toBool());
}

TEST(ParamsDevice, ReadFileRefusesOversizeAndGarbage)
{
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("garbage.vtpar"));
    QFile f(garbage);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{ not json");
    f.close();
    const auto result = model::readParamFile(garbage, dev::Language::English);
    ASSERT_FALSE(result.ok());
    EXPECT_FALSE(result.error().isEmpty());
    EXPECT_FALSE(
        model::readParamFile(dir.filePath(QStringLiteral("missing.vtpar")), dev::Language::English)
            .ok());
}

} // namespace
} // namespace vt::test
