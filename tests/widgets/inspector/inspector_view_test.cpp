// InspectorView: the live list fed by a simulator session, the
// detail pane of the selected frame (CANopen images unwrapped), filters, pause, save (CSV and
// text), and linked navigation in both directions.
#include "canopen/can_frame.h"
#include "model/inspect/field_tree_model.h"
#include "model/telegrams/telegram_log_model.h"
#include "sim_connection.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/frame_detail.h"
#include "widgets/inspector/hex_view.h"
#include "widgets/inspector/inspector_view.h"

#include <QFile>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

using namespace vt;
using vt::dev::Direction;
using vt::ui::InspectorView;

namespace {

QByteArray qt(const dev::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), static_cast<qsizetype>(b.size()));
}

// Reads d1.07 through the session so that the list has a real exchange.
bool readD107(test::LoggedSim &rig)
{
    const dev::ParamMeta *row = rig.modules.front().dictionary->find("d1.07");
    if (!row)
        return false;
    bool done = false;
    auto plan = rig.connection->session().adapter().planRead(
        rig.modules.front().address, std::span<const dev::ParamMeta *const>(&row, 1));
    if (plan.empty())
        return false;
    rig.connection->session().submit(plan.front(), model::Priority::User,
                                     [&](const model::Outcome &) { done = true; });
    const bool ok = test::waitUntil([&] { return done; }, test::kWaitMs);
    rig.log->flush();
    return ok;
}

} // namespace

TEST(InspectorView, ListsTheSessionsFramesAndExplainsTheSelectedOne)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51"));
    InspectorView view;
    view.resize(1200, 800);
    view.show();
    view.setLog(rig.log.get());
    view.setConnection(rig.connection.get(), rig.modules);
    ASSERT_TRUE(readD107(rig));
    ASSERT_GE(view.logModel()->rowCount(), 2);
    view.table()->selectRow(0);
    EXPECT_TRUE(view.frameDetail()->selectField("pdu.function") ||
                view.frameDetail()->selectField("function"))
        << view.frameDetail()->headline().toStdString();
    EXPECT_EQ(view.parametersOfCurrent(), QStringList{"d1.07"});
    QSignalSpy activated(&view, &InspectorView::parameterActivated);
    ASSERT_TRUE(view.activateParameterOfCurrent());
    ASSERT_EQ(activated.size(), 1);
    EXPECT_EQ(activated.at(0).at(0).toInt(), rig.modules.front().address);
    EXPECT_EQ(activated.at(0).at(1).toString(), QStringLiteral("d1.07"));
    // The answer row names the same parameter (through its request).
    view.table()->selectRow(1);
    EXPECT_EQ(view.parametersOfCurrent(), QStringList{"d1.07"});
    // Its data word is named after the request's first ID (the answer itself does not carry it).
    const dev::Description &answer = view.frameDetail()->fieldModel()->description();
    bool named = false;
    for (const dev::FieldSpan &f : answer.fields)
        named = named || f.text.en.find("d1.07") != std::string::npos;
    EXPECT_TRUE(named);
}

TEST(InspectorView, ShowFramesForSelectsTheLastExchange)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51"));
    InspectorView view;
    view.setLog(rig.log.get());
    view.setConnection(rig.connection.get(), rig.modules);
    ASSERT_TRUE(readD107(rig));
    ASSERT_TRUE(readD107(rig));
    const int module = rig.modules.front().address;
    // Hide module's frames by an error filter; showFramesFor lifts it.
    model::TelegramFilter errors;
    errors.errorsOnly = true;
    view.setFilter(errors);
    EXPECT_EQ(view.logModel()->rowCount(), 0);
    view.showFramesFor(module, QStringLiteral("d1.07"));
    const QList<quint64> selected = view.selectedSeqs();
    ASSERT_EQ(selected.size(), 2);
    EXPECT_EQ(selected.back(), rig.log->at(rig.log->size() - 1).seq);
    EXPECT_FALSE(view.filter().errorsOnly);
    view.showFramesFor(module, QStringLiteral("C1.07")); // never sent: nothing selected
    EXPECT_TRUE(view.selectedSeqs().isEmpty());
}

TEST(InspectorView, FiltersPauseClearAndCorruptRecords)
{
    model::TelegramLog log;
    InspectorView view;
    view.setLog(&log);
    log.append(Direction::Request, "sim", "modbus-rtu", 1, QByteArray::fromHex("01030007000135CB"));
    log.append(Direction::Response, "sim", "modbus-rtu", 1, QByteArray::fromHex("0103020133FFFF"),
               model::TelegramRecord::Status::ChecksumError, "CRC");
    log.appendTimeout("sim", "modbus-rtu", 2);
    // A CANopen record as the CAN link logs it: 16-byte SocketCAN image.
    const auto image = dev::canopen::toSocketCan(
        dev::canopen::makeCanFrame(0x605, dev::Bytes{0x40, 0x41, 0x60, 0, 0, 0, 0, 0}));
    log.append(Direction::Request, "can0", "canopen", 5,
               qt(dev::Bytes(image.begin(), image.end())));
    log.flush();
    ASSERT_EQ(view.logModel()->rowCount(), 4);

    model::TelegramFilter f;
    f.module = 1;
    view.setFilter(f);
    EXPECT_EQ(view.logModel()->rowCount(), 2);
    f = {};
    f.errorsOnly = true;
    view.setFilter(f);
    EXPECT_EQ(view.logModel()->rowCount(), 2); // checksum error + timeout
    view.table()->selectRow(0);                // the corrupt frame: its error, no crash
    EXPECT_TRUE(view.frameDetail()->headline().contains(QStringLiteral("byte")))
        << view.frameDetail()->headline().toStdString();
    view.table()->selectRow(1); // the timeout: no bytes
    EXPECT_TRUE(view.frameDetail()->hexView()->bytes().isEmpty());
    f = {};
    f.protocol = QStringLiteral("canopen");
    view.setFilter(f);
    ASSERT_EQ(view.logModel()->rowCount(), 1);
    view.table()->selectRow(0);
    ASSERT_TRUE(view.frameDetail()->selectField("sdo.index"));
    EXPECT_EQ(view.frameDetail()->hexView()->highlightOffset(), 9); // inside the SocketCAN image
    EXPECT_EQ(view.frameDetail()->hexView()->highlightLength(), 2);

    view.setFilter({});
    log.setPaused(true);
    log.append(Direction::Request, "sim", "modbus-rtu", 1, QByteArray::fromHex("01030007000135CB"));
    log.flush();
    EXPECT_EQ(view.logModel()->rowCount(), 4); // frozen
    log.setPaused(false);
    log.flush();
    EXPECT_EQ(view.logModel()->rowCount(), 5);
    log.clear();
    EXPECT_EQ(view.logModel()->rowCount(), 0);
    view.setLog(nullptr); // detaches cleanly
    EXPECT_EQ(view.logModel(), nullptr);
}

TEST(InspectorView, SavesCsvAndTextOfWhatTheFilterShows)
{
    model::TelegramLog log;
    InspectorView view;
    view.setLog(&log);
    log.append(Direction::Request, "sim", "modbus-rtu", 1, QByteArray::fromHex("01030007000135CB"));
    log.append(Direction::Request, "sim", "modbus-rtu", 2, QByteArray::fromHex("02030007000135F8"));
    log.flush();
    model::TelegramFilter f;
    f.module = 2;
    view.setFilter(f);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString csv = dir.filePath("t.csv");
    const QString txt = dir.filePath("t.txt");
    QString error;
    ASSERT_TRUE(view.saveCsv(csv, &error)) << error.toStdString();
    ASSERT_TRUE(view.saveText(txt, &error)) << error.toStdString();
    QFile c(csv);
    ASSERT_TRUE(c.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = c.readAll().trimmed().split('\n');
    ASSERT_EQ(lines.size(), 3); // statement line, header, module 2's frame
    EXPECT_TRUE(lines[2].contains("02 03 00 07 00 01 35 F8"));
    QFile t(txt);
    ASSERT_TRUE(t.open(QIODevice::ReadOnly));
    const QByteArray text = t.readAll();
    EXPECT_TRUE(text.contains("02 03 00 07"));
    EXPECT_FALSE(text.contains("01 03 00 07"));
    EXPECT_FALSE(view.saveCsv(dir.filePath("no/such/dir/t.csv"), &error));
}
