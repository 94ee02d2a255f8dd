// valvetune-cli's writes in the session log (model/audit): set, write and test each log their
// items under their own name with the verification result, and the kill test — a valvetune-cli
// set of many settings to a valvetune-sim over TCP, SIGKILLed in the middle once some lines are
// on disk: every line of the log reads, every write logged as verified is on the device, and no
// setting on the device differs from its start value without being in the log, except at most the
// one write that was on the wire.
#include "cli_device_fixture.h"
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/audit/audit_reader.h"
#include "sim_process.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <map>
#include <set>

namespace vt::clitest {
namespace {

using model::AuditEntry;
using model::AuditLogContents;

// The one session log in `dir` (a failure when there is not exactly one).
AuditLogContents onlyLog(const QTemporaryDir &dir)
{
    const QStringList files = QDir(dir.path()).entryList({QStringLiteral("*.jsonl")}, QDir::Files);
    EXPECT_EQ(files.size(), 1) << files.join(' ').toStdString();
    if (files.size() != 1)
        return {};
    const AuditLogContents log = model::readAuditLog(dir.filePath(files.front()));
    EXPECT_TRUE(log.ok) << log.error.toStdString();
    EXPECT_EQ(log.skipped, 0);
    EXPECT_FALSE(log.truncatedTail);
    EXPECT_EQ(log.program, QStringLiteral("valvetune-cli"));
    return log;
}

class CliAudit : public CliDevice
{
protected:
    QStringList logged(QStringList args) const
    {
        return QStringList{"--audit-dir", m_dir.path()} + args + m_sim;
    }
    QTemporaryDir m_dir;
    const QStringList m_sim{"--sim", "dma-pn-v51"};
};

TEST_F(CliAudit, SetLogsEachVerifiedItem)
{
    const CliRun set = cli(logged({"set", "C1.07=1.000", "r1.01=120"}));
    ASSERT_EQ(set.code, cli::kExitOk) << what(set);
    const AuditLogContents log = onlyLog(m_dir);
    EXPECT_TRUE(log.connection.startsWith(QStringLiteral("sim"))) << log.connection.toStdString();
    ASSERT_EQ(log.entries.size(), 2u);
    EXPECT_EQ(log.entries[0].row, QStringLiteral("C1.07"));
    EXPECT_EQ(log.entries[0].newText, QStringLiteral("1.000 V"));
    EXPECT_EQ(log.entries[0].oldText, QStringLiteral("0.000 V"));
    EXPECT_EQ(log.entries[1].row, QStringLiteral("r1.01"));
    for (const AuditEntry &e : log.entries) {
        EXPECT_EQ(e.status, QStringLiteral("verified"));
        EXPECT_EQ(e.origin, QStringLiteral("cli-set"));
        EXPECT_EQ(e.readBack, e.newText);
    }
}

TEST_F(CliAudit, AReadOnlyCommandLeavesNoLog)
{
    ASSERT_EQ(cli(logged({"get", "C1.07"})).code, cli::kExitOk);
    EXPECT_TRUE(QDir(m_dir.path()).entryList(QDir::Files).isEmpty());
}

TEST_F(CliAudit, WriteLogsTheChangedSettingsOfTheFile)
{
    QTemporaryDir files;
    const QString file = files.filePath(QStringLiteral("dma.vtpar"));
    ASSERT_EQ(cli(QStringList{"read", "--out", file} + m_sim).code, cli::kExitOk);
    ASSERT_EQ(cli(QStringList{"set", "C1.07=1.000"} + m_sim).code, cli::kExitOk);
    EXPECT_TRUE(QDir(m_dir.path()).entryList(QDir::Files).isEmpty()); // not logged there
    const CliRun write = cli(logged({"write", file}));
    ASSERT_EQ(write.code, cli::kExitOk) << what(write);
    const AuditLogContents log = onlyLog(m_dir);
    ASSERT_EQ(log.entries.size(), 1u);
    EXPECT_EQ(log.entries[0].row, QStringLiteral("C1.07"));
    EXPECT_EQ(log.entries[0].oldRaw, QStringLiteral("1000"));
    EXPECT_EQ(log.entries[0].newRaw, QStringLiteral("0"));
    EXPECT_EQ(log.entries[0].status, QStringLiteral("verified"));
    EXPECT_EQ(log.entries[0].origin, QStringLiteral("cli-write"));
}

TEST_F(CliAudit, TestLogsTheSourceTheSetValuesAndTheRestore)
{
    ASSERT_EQ(cli(QStringList{"set", "--yes", "E17=0"} + m_sim).code, cli::kExitOk);
    const CliRun test =
        cli(logged({"test", "step", "--from", "3", "--to", "5", "--hold", "0.2", "--yes"}));
    ASSERT_EQ(test.code, cli::kExitOk) << what(test);
    const AuditLogContents log = onlyLog(m_dir);
    std::map<QString, int> rows;
    for (const AuditEntry &e : log.entries) {
        EXPECT_EQ(e.origin, QStringLiteral("cli-test"));
        ++rows[e.row];
    }
    EXPECT_GE(rows[QStringLiteral("A1.01")], 3) << "3 V, 5 V and the restore";
    EXPECT_EQ(rows[QStringLiteral("E17")], 2) << "switched for the test and back";
    EXPECT_EQ(log.entries.back().status, QStringLiteral("verified"));
}

// --- the kill test -----------------------------------------------------------------------------

struct RowValue
{
    std::string display;
    double raw = 0;
};

// The rows' values on the device, from valvetune-cli --json get over TCP.
std::map<std::string, RowValue> deviceValues(const QString &tcp, const QStringList &names)
{
    const CliRun get = cli(QStringList{"--json", "get", "--tcp", tcp} + names);
    EXPECT_EQ(get.code, cli::kExitOk) << what(get);
    std::map<std::string, RowValue> out;
    const auto doc = nlohmann::json::parse(get.out, nullptr, false);
    if (doc.is_discarded() || !doc.contains("values"))
        return out;
    for (const auto &v : doc["values"])
        out[v["name"].get<std::string>()] = {v["display"].get<std::string>(),
                                             v["raw"].get<double>()};
    return out;
}

TEST(CliAuditKill, AKilledWriteSequenceLeavesAReadableCompleteLog)
{
    simtest::Sim sim(
        {"--device", "dma-pn-v51", "--modules", "1", "--factory", "--tcp", "127.0.0.1:0"});
    const QString tcp = sim.listening();
    ASSERT_FALSE(tcp.isEmpty()) << sim.stderrText().toStdString();

    // Controller settings of every mode and version, plain numbers: safe to change on the
    // simulator, none moves the valve, none changes the address or the link.
    const dev::Dictionary *dict = dev::builtinDictionaries()->find("dma-pn-v51");
    ASSERT_TRUE(dict);
    QStringList names;
    for (const dev::ParamMeta &row : dict->params) {
        if (row.block == "C" && row.writable() && row.readable() && !row.movesActuator &&
            !row.isString() && row.enums.empty() && row.bits.empty() && row.modes.empty() &&
            row.versions.empty() && row.minParam.empty() && row.maxParam.empty() &&
            row.min < row.max && names.size() < 24)
            names << QString::fromStdString(row.name);
    }
    ASSERT_GE(names.size(), 8) << "too few rows to write";
    const std::map<std::string, RowValue> start = deviceValues(tcp, names);
    ASSERT_EQ(start.size(), static_cast<std::size_t>(names.size()));
    QStringList assignments;
    for (const QString &name : names) {
        const dev::ParamMeta &row = *dict->find(name.toStdString());
        const double raw = start.at(name.toStdString()).raw == row.min ? row.max : row.min;
        assignments << name + '=' +
                           QString::fromStdString(
                               dev::formatValue(row, raw, dev::Language::English));
    }

    QTemporaryDir dir;
    QProcess writer;
    writer.setProgram(QStringLiteral(VT_CLI_PATH));
    writer.setArguments(QStringList{"--audit-dir", dir.path(), "set", "--tcp", tcp} + assignments);
    writer.start();
    ASSERT_TRUE(writer.waitForStarted(simtest::kWaitMs));

    // Once three writes are logged, SIGKILL: no chance to flush or close anything.
    QString path;
    const auto linesOnDisk = [&] {
        if (path.isEmpty()) {
            const QStringList files = QDir(dir.path()).entryList({"*.jsonl"}, QDir::Files);
            if (files.isEmpty())
                return 0;
            path = dir.filePath(files.front());
        }
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? static_cast<int>(f.readAll().count('\n')) : 0;
    };
    // Polled between short waits on the writer itself (it may end early), bounded.
    QElapsedTimer waited;
    waited.start();
    bool some = false;
    while (!(some = linesOnDisk() >= 4) && writer.state() == QProcess::Running &&
           waited.elapsed() < simtest::kWaitMs)
        writer.waitForFinished(2);
    ASSERT_TRUE(some) << "no write was logged: " << writer.readAllStandardError().toStdString();
    ASSERT_EQ(writer.state(), QProcess::Running) << "the sequence ended before the kill";
    const qint64 pid = writer.processId();
    writer.kill();
    ASSERT_TRUE(writer.waitForFinished(simtest::kWaitMs));

    const AuditLogContents log = model::readAuditLog(path);
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    EXPECT_EQ(log.skipped, 0);
    EXPECT_GE(log.entries.size(), 3u);
    EXPECT_LT(log.entries.size(), static_cast<std::size_t>(names.size())) << "killed in the middle";
    EXPECT_EQ(log.pid, pid);

    const std::map<std::string, RowValue> after = deviceValues(tcp, names);
    ASSERT_EQ(after.size(), start.size());
    std::set<std::string> logged;
    for (const AuditEntry &e : log.entries) {
        EXPECT_EQ(e.origin, QStringLiteral("cli-set"));
        const std::string row = e.row.toStdString();
        logged.insert(row);
        if (e.status == QStringLiteral("verified")) {
            ASSERT_TRUE(after.count(row)) << row;
            EXPECT_EQ(QString::number(after.at(row).raw, 'g', 17), e.newRaw)
                << row << " is logged as verified but not on the device";
        }
    }
    int unlogged = 0;
    for (const auto &[row, value] : after) {
        if (value.raw != start.at(row).raw && !logged.count(row))
            ++unlogged; // only the write on the wire when the kill came may be missing
    }
    EXPECT_LE(unlogged, 1);
}

} // namespace
} // namespace vt::clitest
