// The session log's file (audit_log.h) and its reader (audit_reader.h): the header and the lines
// read back as written, one file per session named by time, program and pid, a line cut by a
// kill reported without losing the lines before it, bad and over-long lines skipped and counted,
// a file over the size limit refused.
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

AuditWriteRecord sample(int n)
{
    AuditWriteRecord w;
    w.time = AuditLog::now();
    w.module = 3;
    w.row = "C1.07";
    w.name = "Set value offset " + std::to_string(n);
    w.unit = "V";
    w.oldValue = {"0.000 V", "0"};
    w.newValue = {"1.000 V", std::to_string(1000 + n)};
    w.status = "verified";
    w.readBack = w.newValue;
    w.reasonEn = "read back 2, expected 1";
    w.reasonDe = "zurückgelesen 2, erwartet 1";
    w.origin = "editor";
    return w;
}

QByteArray contentsOf(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void appendBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::Append));
    ASSERT_EQ(f.write(bytes), bytes.size());
}

TEST(AuditLog, NoFileUntilTheFirstWrite)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1.2.3"), dir.path());
    log.setConnection(QStringLiteral("sim opat"));
    EXPECT_TRUE(log.path().isEmpty());
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

TEST(AuditLog, WritesHeaderConnectionsAndWritesThatReadBack)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1.2.3"), dir.path() + "/sessions");
    log.setConnection(QStringLiteral("tcp 127.0.0.1:502, modbus-tcp"));
    ASSERT_TRUE(log.append(sample(1))) << log.error().toStdString();
    log.setConnection({});
    log.setConnection(QStringLiteral("sim dma-pn-v51"));
    ASSERT_TRUE(log.append(sample(2)));

    const QString name = QFileInfo(log.path()).fileName();
    EXPECT_TRUE(QRegularExpression(QStringLiteral(R"(^\d{8}-\d{6}-valvetune-\d+\.jsonl$)"))
                    .match(name)
                    .hasMatch())
        << name.toStdString();
    EXPECT_TRUE(name.endsWith(QStringLiteral("-%1.jsonl").arg(QCoreApplication::applicationPid())));
    EXPECT_EQ(contentsOf(log.path()).count('\n'), 5); // header, write, 2 connections, write

    const AuditLogContents read = readAuditLog(log.path());
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    EXPECT_EQ(read.program, QStringLiteral("valvetune"));
    EXPECT_EQ(read.version, QStringLiteral("1.2.3"));
    EXPECT_EQ(read.pid, QCoreApplication::applicationPid());
    EXPECT_TRUE(read.started.isValid());
    EXPECT_EQ(read.connection, QStringLiteral("tcp 127.0.0.1:502, modbus-tcp"));
    EXPECT_EQ(read.connections, (std::vector<QString>{{}, QStringLiteral("sim dma-pn-v51")}));
    EXPECT_EQ(read.skipped, 0);
    EXPECT_FALSE(read.truncatedTail);
    ASSERT_EQ(read.entries.size(), 2u);
    const AuditEntry &e = read.entries[1];
    EXPECT_TRUE(e.time.isValid());
    EXPECT_LE(std::abs(e.time.secsTo(QDateTime::currentDateTime())), 60);
    EXPECT_EQ(e.module, 3);
    EXPECT_EQ(e.row, QStringLiteral("C1.07"));
    EXPECT_EQ(e.name, QStringLiteral("Set value offset 2"));
    EXPECT_EQ(e.unit, QStringLiteral("V"));
    EXPECT_EQ(e.oldText, QStringLiteral("0.000 V"));
    EXPECT_EQ(e.oldRaw, QStringLiteral("0"));
    EXPECT_EQ(e.newText, QStringLiteral("1.000 V"));
    EXPECT_EQ(e.newRaw, QStringLiteral("1002"));
    EXPECT_EQ(e.status, QStringLiteral("verified"));
    EXPECT_EQ(e.readBack, QStringLiteral("1.000 V"));
    EXPECT_EQ(e.reason.en, "read back 2, expected 1");
    EXPECT_EQ(e.reason.de, "zurückgelesen 2, erwartet 1");
    EXPECT_EQ(e.origin, QStringLiteral("editor"));
}

TEST(AuditLog, TwoSessionsOfOneProcessInOneSecondGetTwoFiles)
{
    QTemporaryDir dir;
    AuditLog first(QStringLiteral("valvetune-cli"), QStringLiteral("1"), dir.path());
    AuditLog second(QStringLiteral("valvetune-cli"), QStringLiteral("1"), dir.path());
    ASSERT_TRUE(first.append(sample(1)));
    ASSERT_TRUE(second.append(sample(2)));
    EXPECT_NE(first.path(), second.path());
    EXPECT_EQ(readAuditLog(first.path()).entries.size(), 1u);
    EXPECT_EQ(readAuditLog(second.path()).entries.size(), 1u);
}

TEST(AuditLog, CurrentIsTheInstalledLogAndThePreviousComesBack)
{
    QTemporaryDir dir;
    EXPECT_EQ(AuditLog::current(), nullptr);
    AuditLog outer(QStringLiteral("a"), QStringLiteral("1"), dir.path());
    {
        const AuditLog::Scope outerScope(outer);
        EXPECT_EQ(AuditLog::current(), &outer);
        {
            AuditLog inner(QStringLiteral("b"), QStringLiteral("1"), dir.path());
            const AuditLog::Scope innerScope(inner);
            EXPECT_EQ(AuditLog::current(), &inner);
        }
        EXPECT_EQ(AuditLog::current(), &outer);
    }
    EXPECT_EQ(AuditLog::current(), nullptr);
}

TEST(AuditLog, DefaultDirectoryFollowsTheEnvironment)
{
    const QByteArray before = qgetenv("VT_AUDIT_DIR");
    qputenv("VT_AUDIT_DIR", "/tmp/vt-audit-env");
    EXPECT_EQ(AuditLog::defaultDirectory(), QStringLiteral("/tmp/vt-audit-env"));
    qunsetenv("VT_AUDIT_DIR");
    EXPECT_TRUE(AuditLog::defaultDirectory().endsWith(QStringLiteral("/ValveTune/sessions")));
    if (!before.isEmpty())
        qputenv("VT_AUDIT_DIR", before);
}

TEST(AuditLog, UnwritableDirectorySaysWhyAndTheSessionGoesOn)
{
    QTemporaryDir dir;
    QFile blocker(dir.path() + "/file");
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1"), dir.path() + "/file/sessions");
    EXPECT_FALSE(log.append(sample(1)));
    EXPECT_FALSE(log.error().isEmpty());
    EXPECT_FALSE(log.append(sample(2)));
}

// A kill while a line is being written: the lines before it read, the cut one is reported.
TEST(AuditReader, TruncatedLastLineIsReportedNotFatal)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1"), dir.path());
    ASSERT_TRUE(log.append(sample(1)));
    ASSERT_TRUE(log.append(sample(2)));
    const std::string third = formatAuditLine(sample(3));
    appendBytes(log.path(), QByteArray::fromStdString(third.substr(0, third.size() / 2)));

    const AuditLogContents read = readAuditLog(log.path());
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    EXPECT_TRUE(read.truncatedTail);
    EXPECT_EQ(read.skipped, 0);
    ASSERT_EQ(read.entries.size(), 2u);
    EXPECT_EQ(read.entries[1].newRaw, QStringLiteral("1002"));
}

TEST(AuditReader, BadAndOverlongLinesAreSkippedAndCounted)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1"), dir.path());
    ASSERT_TRUE(log.append(sample(1)));
    appendBytes(log.path(), "{not json\n");
    appendBytes(log.path(), "{\"type\":\"write\",\"module\":\"three\",\"status\":\"verified\"}\n");
    appendBytes(log.path(), "{\"type\":\"future\"}\n[1,2]\n\n");
    AuditWriteRecord longOne = sample(2);
    longOne.reasonEn = std::string(200, 'x');
    appendBytes(log.path(), QByteArray::fromStdString(formatAuditLine(longOne)));
    ASSERT_TRUE(log.append(sample(3)));

    AuditLimits limits;
    limits.maxLine = 450;
    const AuditLogContents read = readAuditLog(log.path(), limits);
    ASSERT_TRUE(read.ok) << read.error.toStdString();
    EXPECT_EQ(read.skipped, 5);
    ASSERT_EQ(read.entries.size(), 2u);
    EXPECT_EQ(read.entries[0].newRaw, QStringLiteral("1001"));
    EXPECT_EQ(read.entries[1].newRaw, QStringLiteral("1003"));
    EXPECT_FALSE(read.truncatedTail);
}

TEST(AuditReader, RefusesTooLargeMissingAndHeaderlessFiles)
{
    QTemporaryDir dir;
    AuditLog log(QStringLiteral("valvetune"), QStringLiteral("1"), dir.path());
    ASSERT_TRUE(log.append(sample(1)));
    AuditLimits small;
    small.maxBytes = 64;
    const AuditLogContents tooLarge = readAuditLog(log.path(), small);
    EXPECT_FALSE(tooLarge.ok);
    EXPECT_TRUE(tooLarge.error.contains(QStringLiteral("larger"))) << tooLarge.error.toStdString();

    EXPECT_FALSE(readAuditLog(dir.path() + "/missing.jsonl").ok);

    const QString headerless = dir.path() + "/headerless.jsonl";
    appendBytes(headerless, QByteArray::fromStdString(formatAuditLine(sample(1))));
    const AuditLogContents noHeader = readAuditLog(headerless);
    EXPECT_FALSE(noHeader.ok);
    EXPECT_FALSE(noHeader.error.isEmpty());
}

TEST(AuditRecord, EveryLineFormatsAndParsesBackEqual)
{
    AuditHeaderRecord header{"valvetune-cli", "0.9", 4242, AuditLog::now(), "sim opat"};
    AuditWriteRecord write = sample(7);
    write.oldValue = {};     // not known
    write.readBack = {};     // not read back
    write.reasonDe = "\xff"; // invalid UTF-8 from a device is replaced, not thrown about
    const std::string text = formatAuditLine(header) +
                             formatAuditLine(AuditConnectionRecord{AuditLog::now(), ""}) +
                             formatAuditLine(write);
    const AuditParse parsed = parseAuditLog(text);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.header, header);
    ASSERT_EQ(parsed.connections.size(), 1u);
    EXPECT_TRUE(parsed.connections[0].connection.empty());
    ASSERT_EQ(parsed.writes.size(), 1u);
    EXPECT_EQ(parsed.writes[0].oldValue, AuditValue{});
    EXPECT_EQ(parsed.writes[0].readBack, AuditValue{});
    EXPECT_EQ(parsed.writes[0].newValue, write.newValue);
    EXPECT_FALSE(parsed.writes[0].reasonDe.empty());
}

} // namespace
} // namespace vt::model
