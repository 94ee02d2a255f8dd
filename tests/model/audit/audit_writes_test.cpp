// The session engine's writes reach the session log (write_audit.h) against the built-in
// simulator: a WriteJob's items with their read back (verified, refused before sending,
// not sent after a lost link; an unchanged row sent nothing and is not logged), a write without
// read back through DeviceAccess::write (written / refused by the device), and the connection the
// writes went to.
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "model/session/actuator_ledger.h"
#include "model/session/actuator_restore.h"
#include "model/session/write_job.h"
#include "sim_rig.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <map>

namespace vt::test {
namespace {

using model::AuditEntry;
using model::AuditLog;
using model::AuditOrigin;
using model::WriteItem;
using model::WriteJob;

struct LoggedRig
{
    QTemporaryDir dir;
    AuditLog log{QStringLiteral("valvetune"), QStringLiteral("test"), dir.path()};
    AuditLog::Scope scope{log};
    std::unique_ptr<SimRig> rig = connectSim({"dma-pn-v51", 1, {}, {}, {}});

    model::AuditLogContents read() const { return model::readAuditLog(log.path()); }
};

WriteItem item(const SimRig &rig, const char *name, double raw)
{
    WriteItem i;
    i.row = &rig.row(name);
    i.value = raw;
    return i;
}

bool runJob(WriteJob &job)
{
    QSignalSpy finished(&job, &WriteJob::finished);
    job.start();
    return finished.wait(kWaitMs) || finished.count() > 0;
}

TEST(AuditWrites, AWriteJobLogsEveryItemSentOrRefusedWithItsVerification)
{
    LoggedRig r;
    ASSERT_TRUE(r.rig);
    const double before = r.rig->read("C1.07").value_or(-1);
    WriteItem same = item(*r.rig, "r1.01", 0);
    same.before = dev::RawValue{*r.rig->read("r1.01")};
    same.value = *same.before;
    WriteJob job(
        r.rig->access(), r.rig->module().address, *r.rig->module().dictionary,
        {item(*r.rig, "C1.07", before == 1000 ? 1001 : 1000), item(*r.rig, "C1.07", 10000), same},
        AuditOrigin::Editor);
    ASSERT_TRUE(runJob(job));

    const model::AuditLogContents log = r.read();
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    EXPECT_TRUE(log.connection.startsWith(QStringLiteral("sim")) ||
                (!log.connections.empty() && log.connections.back().startsWith("sim")))
        << log.connection.toStdString();
    ASSERT_EQ(log.entries.size(), 2u); // the unchanged row sent nothing
    std::map<QString, const AuditEntry *> byStatus;
    for (const AuditEntry &e : log.entries) {
        byStatus[e.status] = &e;
        EXPECT_EQ(e.origin, QStringLiteral("editor"));
        EXPECT_EQ(e.module, r.rig->module().address);
    }
    ASSERT_TRUE(byStatus.count("verified") && byStatus.count("refused-locally"));
    const AuditEntry &verified = *byStatus["verified"];
    EXPECT_EQ(verified.row, QStringLiteral("C1.07"));
    EXPECT_FALSE(verified.name.isEmpty());
    EXPECT_EQ(verified.newRaw, before == 1000 ? QStringLiteral("1001") : QStringLiteral("1000"));
    EXPECT_EQ(verified.readBack, verified.newText);
    EXPECT_FALSE(verified.newText.isEmpty());
    // The dictionary's range error in both languages.
    const AuditEntry &refused = *byStatus["refused-locally"];
    EXPECT_FALSE(refused.reason.en.empty());
    EXPECT_FALSE(refused.reason.de.empty());
    EXPECT_NE(refused.reason.en, refused.reason.de);
}

TEST(AuditWrites, AWriteWithoutReadBackIsLoggedUnderItsOrigin)
{
    LoggedRig r;
    ASSERT_TRUE(r.rig);
    ASSERT_TRUE(r.rig->read("C1.07")); // the image knows the value before
    std::optional<model::Outcome> done;
    r.rig->access().write(r.rig->module().address, r.rig->row("C1.07"), dev::RawValue{1234.0},
                          model::Priority::User, AuditOrigin::Workbench,
                          [&](const model::Outcome &o) { done = o; });
    ASSERT_TRUE(waitFor(done));
    ASSERT_EQ(done->status, model::OutcomeStatus::Ok);

    const model::AuditLogContents log = r.read();
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    ASSERT_EQ(log.entries.size(), 1u);
    EXPECT_EQ(log.entries[0].status, QStringLiteral("written"));
    EXPECT_EQ(log.entries[0].origin, QStringLiteral("workbench"));
    EXPECT_EQ(log.entries[0].newRaw, QStringLiteral("1234"));
    EXPECT_FALSE(log.entries[0].oldRaw.isEmpty());
}

TEST(AuditWrites, WithoutAnOriginTheCallerLogsAndWithoutALogNothingIsWritten)
{
    LoggedRig r;
    ASSERT_TRUE(r.rig);
    std::optional<model::Outcome> done;
    r.rig->access().write(r.rig->module().address, r.rig->row("C1.07"), dev::RawValue{1235.0},
                          model::Priority::User, std::nullopt,
                          [&](const model::Outcome &o) { done = o; });
    ASSERT_TRUE(waitFor(done));
    EXPECT_TRUE(r.log.path().isEmpty()); // the WriteJob's case: it logs the verified item itself
}

TEST(AuditWrites, ALostLinkLogsTheUncertainAndTheUnsentRows)
{
    SimSetup setup{"dma-pn-v51", 1, {}, {}, {}};
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("test"), dir.path());
    const AuditLog::Scope scope(log);
    auto rig = connectSim(setup);
    ASSERT_TRUE(rig);
    WriteJob job(rig->access(), rig->module().address, *rig->module().dictionary,
                 {item(*rig, "C1.07", 1100), item(*rig, "C1.08", 1200), item(*rig, "C2.07", 1300)},
                 AuditOrigin::Fold);
    // The link goes away as the first write leaves: it may or may not have arrived.
    QObject::connect(
        &rig->session(), &model::Session::frameSent, &job, [&rig] { rig->connection->close(); },
        Qt::SingleShotConnection);
    ASSERT_TRUE(runJob(job));

    const model::AuditLogContents read = model::readAuditLog(log.path());
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    ASSERT_EQ(read.entries.size(), 3u);
    EXPECT_EQ(read.entries[0].status, QStringLiteral("uncertain"));
    EXPECT_EQ(read.entries[1].status, QStringLiteral("not-sent"));
    EXPECT_EQ(read.entries[2].status, QStringLiteral("not-sent"));
    for (const AuditEntry &e : read.entries)
        EXPECT_EQ(e.origin, QStringLiteral("fold"));
    // The disconnect is a line of its own.
    ASSERT_FALSE(read.connections.empty());
    EXPECT_TRUE(read.connections.back().isEmpty());
}

// Putting back what a valve-moving write changed (stop, disconnect, quit) is a write of its own.
TEST(AuditWrites, PuttingTheSetValueBackIsLoggedAsARestore)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("test"), dir.path());
    const AuditLog::Scope scope(log);
    auto rig = connectSim("dma-pn-v51");
    ASSERT_TRUE(rig);
    model::ActuatorLedger ledger(rig->access().image());
    WriteItem two = item(*rig, "A1.01", 2000);
    two.before = dev::RawValue{*rig->read("A1.01")}; // as the monitor's step knows it
    WriteJob step(rig->access(), rig->module().address, *rig->module().dictionary, {two},
                  AuditOrigin::Monitor);
    ASSERT_TRUE(runJob(step));
    ASSERT_FALSE(ledger.empty());

    model::ActuatorRestore restore(rig->access(), ledger.restorePlan(),
                                   {{rig->module().address, rig->module().dictionary}});
    QSignalSpy finished(&restore, &model::ActuatorRestore::finished);
    restore.start();
    ASSERT_TRUE(finished.wait(kWaitMs) || finished.count() > 0);

    const model::AuditLogContents read = model::readAuditLog(log.path());
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    ASSERT_EQ(read.entries.size(), 2u);
    EXPECT_EQ(read.entries[0].origin, QStringLiteral("monitor"));
    EXPECT_EQ(read.entries[1].origin, QStringLiteral("restore"));
    EXPECT_EQ(read.entries[1].row, QStringLiteral("A1.01"));
    EXPECT_EQ(read.entries[1].oldRaw, QStringLiteral("2000"));
    EXPECT_EQ(read.entries[1].newRaw, read.entries[0].oldRaw);
    EXPECT_EQ(read.entries[1].status, QStringLiteral("verified"));
}

} // namespace
} // namespace vt::test
