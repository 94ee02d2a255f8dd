// TelegramLog: issue #6 (bounded log of every frame, monotonic time, link) and the store side
// of issue #8 (inspector: filters, pause, clear, CSV and text export).
#include "modbus/crc.h"
#include "model/telegrams/telegram_log.h"
#include "resident_memory.h"

#include <QBuffer>
#include <QSignalSpy>
#include <gtest/gtest.h>
#include <vector>

using vt::dev::Direction;
using vt::model::TelegramFilter;
using vt::model::TelegramLog;
using vt::model::TelegramRecord;
using Status = TelegramRecord::Status;

namespace {

const QString kLink = QStringLiteral("serial /dev/ttyUSB0 19200 8E1");
const QString kRtu = QStringLiteral("modbus-rtu");

QByteArray rtu(std::vector<std::uint8_t> adu)
{
    const std::uint16_t crc = vt::dev::modbus::crc16(adu);
    adu.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    adu.push_back(static_cast<std::uint8_t>(crc >> 8));
    return {reinterpret_cast<const char *>(adu.data()), static_cast<qsizetype>(adu.size())};
}

QByteArray payload(int n, char fill = 'x')
{
    return QByteArray(n, fill);
}

QString exported(const TelegramLog &log, bool csv, const TelegramFilter &filter = {},
                 vt::dev::Language language = vt::dev::Language::English)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    vt::model::SummaryOptions options;
    options.language = language;
    const bool ok =
        csv ? log.writeCsv(buffer, options, filter) : log.writeText(buffer, options, filter);
    EXPECT_TRUE(ok);
    return QString::fromUtf8(buffer.data());
}

} // namespace

TEST(TelegramLog, RingWrapKeepsTheNewestAndCountsDropped)
{
    TelegramLog log(5, TelegramLog::kDefaultMaxBytes);
    for (int i = 0; i < 12; ++i)
        EXPECT_EQ(log.append(Direction::Request, kLink, kRtu, 1, QByteArray(1, char(i))),
                  quint64(i));
    EXPECT_EQ(log.size(), 5);
    EXPECT_EQ(log.firstSeq(), 7u);
    EXPECT_EQ(log.nextSeq(), 12u);
    EXPECT_EQ(log.droppedCount(), 7u);
    EXPECT_EQ(log.find(6), nullptr);
    EXPECT_EQ(log.find(12), nullptr);
    ASSERT_NE(log.find(7), nullptr);
    EXPECT_EQ(log.find(7)->bytes, QByteArray(1, char(7)));
    EXPECT_EQ(log.at(0).seq, 7u);
    EXPECT_EQ(log.at(4).seq, 11u);
    EXPECT_EQ(log.storedBytes(), 5 * TelegramLog::recordCost(log.at(0)));
}

// Issue #21 (endurance): the log's memory is taken when it is made; filling it up to its cap and
// running on adds nothing (a 19-byte Modbus TCP reply, the link text made anew for every frame as
// the recorder does).
TEST(TelegramLog, FillingUpToTheCapAndBeyondAddsNoMemory)
{
    if (!vt::test::kResidentMemoryIsMeaningful)
        GTEST_SKIP() << "AddressSanitizer's quarantine keeps every freed temporary resident";
    constexpr qsizetype kRecords = 50'000;
    TelegramLog log(kRecords, TelegramLog::kDefaultMaxBytes);
    const QByteArray reply = payload(19);
    const qint64 before = vt::test::residentBytes();
    ASSERT_GT(before, 0);
    for (qsizetype i = 0; i < 2 * kRecords; ++i)
        log.append(i % 2 ? Direction::Response : Direction::Request,
                   QStringLiteral("sim dma-pn-v51 ×%1").arg(3), kRtu, 1, reply);
    EXPECT_EQ(log.size(), kRecords);
    EXPECT_EQ(log.at(0).bytes, reply);
    // A log that grew per record would hold ≥ 50 000 × (sizeof(TelegramRecord) + one frame and
    // one link text on the heap) ≈ 10 MB more now.
    EXPECT_LT(vt::test::residentBytes() - before, 1024 * 1024);
}

TEST(TelegramLog, LongFramesAndNotesKeepTheirBytesWhileHeld)
{
    TelegramLog log(3, TelegramLog::kDefaultMaxBytes);
    const QByteArray longFrame = payload(300, 'L');
    log.append(Direction::Response, kLink, kRtu, 1, longFrame, Status::DeviceException,
               QStringLiteral("illegal data address"));
    const QByteArray held = log.at(0).bytes; // a view holding a copy
    log.append(Direction::Request, kLink, kRtu, 1, payload(5, 'a'));
    log.append(Direction::Request, kLink, kRtu, 1, payload(40, 'b'));
    EXPECT_EQ(log.at(0).bytes, longFrame);
    EXPECT_EQ(log.at(0).note, QStringLiteral("illegal data address"));
    EXPECT_EQ(log.at(2).bytes, payload(40, 'b'));
    // The slot of the long frame is reused; the copy a view held is untouched.
    log.append(Direction::Request, kLink, kRtu, 1, payload(2, 'c'));
    log.append(Direction::Request, kLink, kRtu, 1, payload(3, 'd'));
    EXPECT_EQ(held, longFrame);
    EXPECT_EQ(log.at(0).bytes, payload(40, 'b'));
    EXPECT_TRUE(log.at(0).note.isEmpty());
    EXPECT_EQ(log.at(2).bytes, payload(3, 'd'));
    EXPECT_EQ(log.storedBytes(), TelegramLog::recordCost(log.at(0)) +
                                     TelegramLog::recordCost(log.at(1)) +
                                     TelegramLog::recordCost(log.at(2)));
    log.append(Direction::Response, kLink, kRtu, 1, {}, Status::Timeout);
    EXPECT_TRUE(log.at(2).bytes.isEmpty());
    log.setLimits(5, TelegramLog::kDefaultMaxBytes); // a larger ring keeps every record
    EXPECT_EQ(log.size(), 3);
    EXPECT_EQ(log.at(0).bytes, payload(2, 'c'));
    log.append(Direction::Request, kLink, kRtu, 1, payload(1, 'e'));
    EXPECT_EQ(log.size(), 4);
    EXPECT_EQ(log.at(3).seq, log.nextSeq() - 1);
}

TEST(TelegramLog, ByteCapDropsTheOldestButKeepsTheNewest)
{
    TelegramRecord probe;
    probe.bytes = payload(1000);
    const qint64 cost = TelegramLog::recordCost(probe);
    TelegramLog log(1000, 3 * cost + cost / 2);
    for (int i = 0; i < 10; ++i)
        log.append(Direction::Response, kLink, kRtu, 1, payload(1000));
    EXPECT_EQ(log.size(), 3);
    EXPECT_EQ(log.droppedCount(), 7u);
    EXPECT_LE(log.storedBytes(), log.maxBytes());

    // One frame larger than the cap on its own is still kept (the newest always is).
    log.append(Direction::Response, kLink, kRtu, 1, payload(10'000));
    EXPECT_EQ(log.size(), 1);
    EXPECT_EQ(log.at(0).bytes.size(), 10'000);

    log.setLimits(1000, 100 * cost);
    for (int i = 0; i < 5; ++i)
        log.append(Direction::Response, kLink, kRtu, 1, payload(1000));
    log.setLimits(2, 100 * cost); // lowering a cap drops at once
    EXPECT_EQ(log.size(), 2);
    EXPECT_EQ(log.storedBytes(), 2 * cost);
}

TEST(TelegramLog, AppendedIsCoalesced)
{
    TelegramLog log;
    QSignalSpy spy(&log, &TelegramLog::appended);
    for (int i = 0; i < 1000; ++i)
        log.append(Direction::Request, kLink, kRtu, 1, payload(8));
    EXPECT_EQ(spy.count(), 0); // nothing per frame
    ASSERT_TRUE(spy.wait(2000));
    ASSERT_EQ(spy.count(), 1);
    EXPECT_EQ(spy[0][0].value<quint64>(), 0u);
    EXPECT_EQ(spy[0][1].value<qsizetype>(), 1000);

    for (int i = 0; i < 500; ++i)
        log.append(Direction::Response, kLink, kRtu, 1, payload(8));
    log.flush();
    ASSERT_EQ(spy.count(), 2);
    EXPECT_EQ(spy[1][0].value<quint64>(), 1000u);
    EXPECT_EQ(spy[1][1].value<qsizetype>(), 500);
    log.flush(); // nothing new: no signal
    EXPECT_EQ(spy.count(), 2);
}

TEST(TelegramLog, TrimmedComesBeforeAppendedAndSkipsUnannouncedRecords)
{
    TelegramLog log(5, TelegramLog::kDefaultMaxBytes);
    std::vector<QString> events;
    QObject::connect(&log, &TelegramLog::trimmed, [&](quint64 first) {
        events.push_back(QStringLiteral("trim %1").arg(first));
    });
    QObject::connect(&log, &TelegramLog::appended, [&](quint64 first, qsizetype n) {
        events.push_back(QStringLiteral("add %1+%2").arg(first).arg(n));
    });
    for (int i = 0; i < 3; ++i)
        log.append(Direction::Request, kLink, kRtu, 1, payload(4));
    log.flush();
    for (int i = 0; i < 10; ++i) // seqs 3..12; only 8..12 survive
        log.append(Direction::Request, kLink, kRtu, 1, payload(4));
    log.flush();
    EXPECT_EQ(events, (std::vector<QString>{"add 0+3", "trim 8", "add 8+5"}));

    events.clear();
    log.append(Direction::Request, kLink, kRtu, 1, payload(4)); // drops seq 8
    log.flush();
    EXPECT_EQ(events, (std::vector<QString>{"trim 9", "add 13+1"}));
}

TEST(TelegramLog, PauseKeepsRecordingAndHoldsBackTheAnnouncement)
{
    TelegramLog log;
    QSignalSpy appended(&log, &TelegramLog::appended);
    QSignalSpy paused(&log, &TelegramLog::pausedChanged);
    log.setPaused(true);
    for (int i = 0; i < 3; ++i)
        log.append(Direction::Request, kLink, kRtu, 1, payload(4));
    log.flush();
    EXPECT_EQ(log.size(), 3);
    EXPECT_EQ(appended.count(), 0);
    EXPECT_EQ(log.announcedEnd(), 0u);
    log.setPaused(false); // resuming reports at once, in one batch
    ASSERT_EQ(appended.count(), 1);
    EXPECT_EQ(appended[0][1].value<qsizetype>(), 3);
    EXPECT_EQ(paused.count(), 2);
}

TEST(TelegramLog, ClearEmptiesButSeqsGoOn)
{
    TelegramLog log(2, TelegramLog::kDefaultMaxBytes);
    QSignalSpy cleared(&log, &TelegramLog::cleared);
    QSignalSpy appended(&log, &TelegramLog::appended);
    for (int i = 0; i < 4; ++i)
        log.append(Direction::Request, kLink, kRtu, 1, payload(4));
    log.clear();
    EXPECT_EQ(cleared.count(), 1);
    EXPECT_TRUE(log.isEmpty());
    EXPECT_EQ(log.droppedCount(), 0u);
    EXPECT_EQ(log.storedBytes(), 0);
    log.flush();
    EXPECT_EQ(appended.count(), 0); // what was cleared is never announced
    EXPECT_EQ(log.append(Direction::Request, kLink, kRtu, 1, payload(4)), 4u);
    EXPECT_EQ(log.firstSeq(), 4u);
}

TEST(TelegramLog, StampsMonotonicAndWallClockTimes)
{
    TelegramLog log;
    log.append(Direction::Request, kLink, kRtu, 1, payload(4));
    log.append(Direction::Response, kLink, kRtu, 1, payload(4));
    EXPECT_GE(log.at(0).monotonicNs, 0);
    EXPECT_GE(log.at(1).monotonicNs, log.at(0).monotonicNs);
    EXPECT_TRUE(log.at(0).wallClock.isValid());
    EXPECT_EQ(log.at(0).wallClock.timeSpec(), Qt::UTC);

    TelegramRecord given; // a caller that stamped the frame itself keeps its times
    given.monotonicNs = 42;
    given.wallClock = QDateTime(QDate(2024, 5, 1), QTime(10, 0), Qt::UTC);
    log.append(given);
    EXPECT_EQ(log.at(2).monotonicNs, 42);
    EXPECT_EQ(log.at(2).wallClock, given.wallClock);
    EXPECT_EQ(log.at(2).seq, 2u);
}

TEST(TelegramLog, TimeoutIsARecordWithoutBytes)
{
    TelegramLog log;
    log.appendTimeout(kLink, kRtu, 3, QStringLiteral("after 3 retries"));
    const TelegramRecord &r = log.at(0);
    EXPECT_EQ(r.status, Status::Timeout);
    EXPECT_TRUE(r.bytes.isEmpty());
    EXPECT_EQ(r.direction, Direction::Response);
    EXPECT_EQ(r.module, 3);
    EXPECT_TRUE(r.isError());
    EXPECT_EQ(TelegramLog::summary(r), QStringLiteral("no reply: after 3 retries"));
}

TEST(TelegramLog, SummaryComesFromDescribeAnyInTheChosenLanguage)
{
    TelegramRecord r;
    r.protocol = kRtu;
    r.bytes = rtu({0x01, 0x03, 0x00, 0x07, 0x00, 0x07}); // FC 3: 7 registers from 0x0007
    vt::model::SummaryOptions en;
    vt::model::SummaryOptions de;
    de.language = vt::dev::Language::German;
    EXPECT_TRUE(TelegramLog::summary(r, en).contains(QStringLiteral("(unit 1)")))
        << TelegramLog::summary(r, en).toStdString();
    EXPECT_TRUE(TelegramLog::summary(r, de).contains(QStringLiteral("(Gerät 1)")))
        << TelegramLog::summary(r, de).toStdString();
    r.bytes[2] = char(0x01); // broken CRC: still one line, saying so
    EXPECT_TRUE(TelegramLog::summary(r, en).startsWith(QStringLiteral("invalid Modbus frame")))
        << TelegramLog::summary(r, en).toStdString();
    r.protocol = QStringLiteral("no-such-protocol");
    EXPECT_EQ(TelegramLog::summary(r, en), QStringLiteral("8 byte(s)"));
}

namespace {

void fill(TelegramLog &log)
{
    const QDateTime t0(QDate(2024, 5, 1), QTime(10, 0, 0, 250), Qt::UTC);
    TelegramRecord q;
    q.monotonicNs = 1'000'345'678;
    q.wallClock = t0;
    q.link = kLink;
    q.protocol = kRtu;
    q.module = 1;
    q.bytes = rtu({0x01, 0x03, 0x00, 0x07, 0x00, 0x07});
    log.append(q);
    TelegramRecord a = q;
    a.monotonicNs = 1'020'000'000;
    a.wallClock = t0.addMSecs(20);
    a.direction = Direction::Response;
    a.bytes = QByteArray::fromHex("0103ff");
    a.status = Status::Malformed;
    a.note = QStringLiteral("truncated, \"CNT\" says 14");
    log.append(a);
    TelegramRecord t;
    t.monotonicNs = 1'100'000'000;
    t.wallClock = t0.addMSecs(100);
    t.direction = Direction::Response;
    t.link = QStringLiteral("tcp 127.0.0.1:502");
    t.protocol = QStringLiteral("modbus-tcp");
    t.status = Status::Timeout;
    log.append(t);
}

} // namespace

TEST(TelegramLog, CsvHasOneQuotedRowPerRecord)
{
    TelegramLog log;
    fill(log);
    QStringList lines = exported(log, true).split(QLatin1Char('\n'));
    ASSERT_EQ(lines.size(), 6); // format statement, header, 3 rows, trailing empty
    EXPECT_EQ(lines.takeFirst(), "# ValveTune telegram log. Separator: comma (,). Decimal sign: "
                                 "point (.). Encoding: UTF-8.");
    EXPECT_EQ(lines[0],
              "seq,time_s,wall_clock_utc,direction,link,protocol,module,bytes,status,summary,note");
    EXPECT_EQ(
        lines[1],
        "0,1.000345678,2024-05-01T10:00:00.250Z,request,serial /dev/ttyUSB0 19200 8E1,modbus-rtu,1,"
        "01 03 00 07 00 07 B5 C9,ok,FC 3 read 7 register(s) from 0x0007 (unit 1),");
    EXPECT_TRUE(lines[2].startsWith("1,1.020000000,2024-05-01T10:00:00.270Z,response,"))
        << lines[2].toStdString();
    EXPECT_TRUE(lines[2].contains(",01 03 FF,malformed,invalid Modbus frame: truncated at byte 3"))
        << lines[2].toStdString();
    EXPECT_TRUE(lines[2].endsWith(",\"truncated, \"\"CNT\"\" says 14\"")) << lines[2].toStdString();
    EXPECT_EQ(lines[3], "2,1.100000000,2024-05-01T10:00:00.350Z,response,tcp "
                        "127.0.0.1:502,modbus-tcp,,,timeout,no reply,");
    EXPECT_TRUE(lines[4].isEmpty());
}

// German and English issue: a German export uses ';' between fields and ',' as decimal sign, and
// its first line says so.
TEST(TelegramLog, GermanCsvUsesSemicolonAndDecimalComma)
{
    TelegramLog log;
    fill(log);
    QStringList lines = exported(log, true, {}, vt::dev::Language::German).split(QLatin1Char('\n'));
    ASSERT_EQ(lines.size(), 6);
    EXPECT_EQ(lines[0], "# ValveTune-Telegrammprotokoll. Trennzeichen: Semikolon (;). "
                        "Dezimalzeichen: Komma (,). Kodierung: UTF-8.");
    EXPECT_EQ(lines[1],
              "seq;time_s;wall_clock_utc;direction;link;protocol;module;bytes;status;summary;note");
    EXPECT_TRUE(
        lines[2].startsWith("0;1,000345678;2024-05-01T10:00:00.250Z;request;serial "
                            "/dev/ttyUSB0 19200 8E1;modbus-rtu;1;01 03 00 07 00 07 B5 C9;ok;"))
        << lines[2].toStdString();
    // The note holds a quote, so it is quoted; its comma needs no quoting of its own.
    EXPECT_TRUE(lines[3].endsWith(";\"truncated, \"\"CNT\"\" says 14\"")) << lines[3].toStdString();
    EXPECT_TRUE(lines[4].startsWith(
        "2;1,100000000;2024-05-01T10:00:00.350Z;response;tcp 127.0.0.1:502;modbus-tcp;;;timeout;"))
        << lines[4].toStdString();
}

TEST(TelegramLog, TextDumpIsReadable)
{
    TelegramLog log(2, TelegramLog::kDefaultMaxBytes);
    fill(log); // three into two: one dropped
    const QString text = exported(log, false);
    EXPECT_TRUE(text.startsWith("ValveTune telegram log: 2 record(s), 1 older record(s) dropped\n"))
        << text.toStdString();
    EXPECT_TRUE(text.contains(
        "#1  1.020000 s  2024-05-01T10:00:00.270Z  in  modbus-rtu  module 1  serial /dev/ttyUSB0"))
        << text.toStdString();
    EXPECT_TRUE(text.contains("\n    01 03 FF\n"));
    EXPECT_TRUE(text.contains("\n    malformed: truncated, \"CNT\" says 14\n"));
    EXPECT_TRUE(text.contains("\n    no reply\n    timeout\n"));
    EXPECT_FALSE(text.contains("#0 "));
}

TEST(TelegramLog, FiltersSelectWhatIsSaved)
{
    TelegramLog log;
    fill(log);
    TelegramFilter errors;
    errors.errorsOnly = true;
    // Each count: the format statement, the header, then the records the filter accepts.
    EXPECT_EQ(exported(log, true, errors).count(QLatin1Char('\n')), 4); // 2 errors
    TelegramFilter tcp;
    tcp.protocol = QStringLiteral("modbus-tcp");
    EXPECT_EQ(exported(log, true, tcp).count(QLatin1Char('\n')), 3);
    TelegramFilter module;
    module.module = 1;
    EXPECT_EQ(exported(log, true, module).count(QLatin1Char('\n')), 4);
    module.module = 2;
    EXPECT_EQ(exported(log, true, module).count(QLatin1Char('\n')), 2);
}

TEST(TelegramLog, WriteErrorsAreReported)
{
    TelegramLog log;
    fill(log);
    QBuffer closed;
    QString error;
    EXPECT_FALSE(log.writeCsv(closed, {}, {}, &error));
    EXPECT_FALSE(error.isEmpty());
}
