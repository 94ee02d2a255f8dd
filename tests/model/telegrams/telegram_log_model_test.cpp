// TelegramLogModel: the inspector's table (issue #8) follows the bounded log row by row —
// appended at the bottom, dropped from the top — and filters by module, protocol and errors.
#include "model/telegrams/telegram_log_model.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <gtest/gtest.h>
#include <memory>

using vt::dev::Direction;
using vt::model::TelegramFilter;
using vt::model::TelegramLog;
using vt::model::TelegramLogModel;
using Status = vt::model::TelegramRecord::Status;

namespace {

const QString kLink = QStringLiteral("sim dma");

struct Fixture
{
    explicit Fixture(qsizetype capacity = 5)
        : log(capacity, TelegramLog::kDefaultMaxBytes), model(&log),
          tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal)
    {
    }
    void add(int module, const QString &protocol = QStringLiteral("modbus-rtu"),
             Status status = Status::Ok)
    {
        log.append(Direction::Request, kLink, protocol, module, QByteArray::fromHex("0103"),
                   status);
    }
    std::vector<quint64> seqs() const
    {
        std::vector<quint64> out;
        for (int row = 0; row < model.rowCount(); ++row)
            out.push_back(model.seqAt(row));
        return out;
    }

    TelegramLog log;
    TelegramLogModel model;
    QAbstractItemModelTester tester;
};

} // namespace

TEST(TelegramLogModel, RowsFollowTheRingAcrossWrapAround)
{
    Fixture f(5);
    QSignalSpy inserted(&f.model, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(&f.model, &QAbstractItemModel::rowsRemoved);
    for (int i = 0; i < 3; ++i)
        f.add(1);
    EXPECT_EQ(f.model.rowCount(), 0); // coalesced: rows arrive with the log's notification
    f.log.flush();
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{0, 1, 2}));
    EXPECT_EQ(inserted.count(), 1);

    for (int i = 0; i < 4; ++i)
        f.add(1);
    f.log.flush();
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{2, 3, 4, 5, 6}));
    ASSERT_EQ(removed.count(), 1);
    EXPECT_EQ(removed[0][1].toInt(), 0);
    EXPECT_EQ(removed[0][2].toInt(), 1);
    EXPECT_EQ(inserted.count(), 2);

    for (int i = 0; i < 23; ++i) // more than the whole ring in one batch
        f.add(1);
    ASSERT_TRUE(QSignalSpy(&f.log, &TelegramLog::appended).wait(2000));
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{25, 26, 27, 28, 29}));
    EXPECT_EQ(f.model.rowOfSeq(27), 2);
    EXPECT_EQ(f.model.rowOfSeq(3), -1);
    ASSERT_NE(f.model.recordAt(4), nullptr);
    EXPECT_EQ(f.model.recordAt(4)->seq, 29u);
}

TEST(TelegramLogModel, ColumnsAndHeaders)
{
    Fixture f;
    f.log.append(Direction::Request, kLink, QStringLiteral("modbus-rtu"), 2,
                 QByteArray::fromHex("0103"));
    f.log.appendTimeout(kLink, QStringLiteral("modbus-rtu"), -1);
    f.log.append(Direction::Response, kLink, QStringLiteral("hart"), 0, QByteArray::fromHex("06"),
                 Status::DeviceException, QStringLiteral("busy"));
    f.log.flush();
    ASSERT_EQ(f.model.rowCount(), 3);
    EXPECT_EQ(f.model.columnCount(), TelegramLogModel::ColumnCount);
    const auto text = [&](int row, int column) {
        return f.model.index(row, column).data().toString();
    };
    EXPECT_EQ(text(0, TelegramLogModel::DirectionColumn), "out");
    EXPECT_EQ(text(1, TelegramLogModel::DirectionColumn), "in");
    EXPECT_EQ(text(0, TelegramLogModel::LinkColumn), kLink);
    EXPECT_EQ(text(0, TelegramLogModel::ProtocolColumn), "modbus-rtu");
    EXPECT_EQ(text(0, TelegramLogModel::ModuleColumn), "2");
    EXPECT_EQ(text(1, TelegramLogModel::ModuleColumn), "");
    EXPECT_EQ(text(1, TelegramLogModel::SummaryColumn), "no reply");
    EXPECT_EQ(text(1, TelegramLogModel::StatusColumn), "timeout");
    EXPECT_EQ(text(2, TelegramLogModel::StatusColumn), "device exception: busy");
    EXPECT_FALSE(text(0, TelegramLogModel::TimeColumn).isEmpty());
    EXPECT_TRUE(f.model.index(2, 0).data(TelegramLogModel::IsErrorRole).toBool());
    EXPECT_FALSE(f.model.index(0, 0).data(TelegramLogModel::IsErrorRole).toBool());
    EXPECT_EQ(f.model.index(2, 0).data(TelegramLogModel::StatusRole).toInt(),
              int(Status::DeviceException));
    EXPECT_EQ(f.model.index(0, 0).data(TelegramLogModel::BytesRole).toByteArray(),
              QByteArray::fromHex("0103"));
    EXPECT_EQ(f.model.index(1, 0).data(TelegramLogModel::SeqRole).value<quint64>(), 1u);
    EXPECT_EQ(f.model.index(0, TelegramLogModel::SummaryColumn).data(Qt::ToolTipRole).toString(),
              "01 03");

    const QStringList headers = {"Time [s]", "Dir",     "Link",  "Protocol",
                                 "Module",   "Summary", "Status"};
    for (int c = 0; c < TelegramLogModel::ColumnCount; ++c)
        EXPECT_EQ(f.model.headerData(c, Qt::Horizontal).toString(), headers[c]);
}

TEST(TelegramLogModel, FiltersByModuleProtocolAndErrors)
{
    Fixture f(100);
    f.add(1);
    f.add(2);
    f.add(1, QStringLiteral("hart"));
    f.add(2, QStringLiteral("modbus-rtu"), Status::ChecksumError);
    f.log.flush();
    ASSERT_EQ(f.model.rowCount(), 4);

    QSignalSpy reset(&f.model, &QAbstractItemModel::modelReset);
    TelegramFilter byModule;
    byModule.module = 2;
    f.model.setFilter(byModule);
    EXPECT_EQ(reset.count(), 1);
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{1, 3}));

    TelegramFilter byProtocol;
    byProtocol.protocol = QStringLiteral("hart");
    f.model.setFilter(byProtocol);
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{2}));

    TelegramFilter errors;
    errors.errorsOnly = true;
    f.model.setFilter(errors);
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{3}));
    f.add(1); // new rows pass through the same filter
    f.add(1, QStringLiteral("hart"), Status::Timeout);
    f.log.flush();
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{3, 5}));

    f.model.setFilter({});
    EXPECT_EQ(f.model.rowCount(), 6);
}

TEST(TelegramLogModel, FilteredRowsLeaveTheTopWhenTheRingDrops)
{
    Fixture f(4);
    TelegramFilter module1;
    module1.module = 1;
    f.model.setFilter(module1);
    f.add(1); // 0
    f.add(2); // 1
    f.add(1); // 2
    f.add(2); // 3
    f.log.flush();
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{0, 2}));
    f.add(2); // 4, drops 0
    f.add(2); // 5, drops 1
    f.add(2); // 6, drops 2
    f.log.flush();
    EXPECT_EQ(f.model.rowCount(), 0);
}

TEST(TelegramLogModel, PauseFreezesTheRowsClearEmptiesThem)
{
    Fixture f(100);
    f.add(1);
    f.log.flush();
    f.log.setPaused(true);
    f.add(1);
    f.add(1);
    f.log.flush();
    EXPECT_EQ(f.model.rowCount(), 1);
    TelegramFilter all;
    all.errorsOnly = false;
    all.module = 1;
    f.model.setFilter(all); // a rebuild while paused shows no unannounced records either
    EXPECT_EQ(f.model.rowCount(), 1);
    f.log.setPaused(false);
    EXPECT_EQ(f.model.rowCount(), 3);

    QSignalSpy reset(&f.model, &QAbstractItemModel::modelReset);
    f.log.clear();
    EXPECT_EQ(f.model.rowCount(), 0);
    EXPECT_EQ(reset.count(), 1);
    f.add(1);
    f.log.flush();
    EXPECT_EQ(f.seqs(), (std::vector<quint64>{3}));
}

TEST(TelegramLogModel, SummaryLanguageSwitchRefreshesTheRows)
{
    Fixture f;
    f.log.appendTimeout(kLink, QStringLiteral("modbus-rtu"), 1);
    f.log.flush();
    QSignalSpy changed(&f.model, &QAbstractItemModel::dataChanged);
    vt::model::SummaryOptions de;
    de.language = vt::dev::Language::German;
    f.model.setSummaryOptions(de);
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(f.model.summaryOptions().language, vt::dev::Language::German);
}

TEST(TelegramLogModel, SurvivesItsLogGoingAway)
{
    auto log = std::make_unique<TelegramLog>();
    TelegramLogModel model(log.get());
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    log->append(Direction::Request, kLink, QStringLiteral("hart"), 0, QByteArray::fromHex("02"));
    log->flush();
    EXPECT_EQ(model.rowCount(), 1);
    log.reset();
    EXPECT_EQ(model.rowCount(), 0);
    EXPECT_EQ(model.recordAt(0), nullptr);
}
