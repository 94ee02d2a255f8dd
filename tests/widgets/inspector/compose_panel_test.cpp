// The composer: bytes equal the manuals', Send is disabled with a reason where the link
// cannot carry the frame, and a sent frame's answer from the simulator arrives in the log.
#include "hcs/worked_examples.h"
#include "model/audit/audit_log.h"
#include "model/audit/audit_reader.h"
#include "sim_connection.h"
#include "widgets/inspector/compose_panel.h"
#include "widgets/inspector/frame_detail.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace vt;
using vt::dev::inspect::ComposeKind;
using vt::ui::ComposePanel;

TEST(ComposePanel, FieldsMakeTheManualsBytes)
{
    ComposePanel panel;
    panel.setKind(ComposeKind::GatewayWrite); // OPAT manual §2.7
    panel.setFieldText("tadr", "0x23");
    panel.setFieldText("sadr", "0");
    panel.setFieldText("id", "0x0030");
    panel.setFieldText("value", "1000");
    ASSERT_TRUE(panel.composed().has_value()) << panel.problem().toStdString();
    EXPECT_EQ(panel.composed()->bytes, vt::test::hcs_examples::kOpat27Write);
    EXPECT_TRUE(panel.composed()->writes);
    EXPECT_TRUE(panel.detail()->selectField("DAT")); // the preview decodes it

    panel.setKind(ComposeKind::GatewayCyclic); // OPAT manual §3.4.2
    panel.setFamily(dev::hcs::Family::Opat);
    panel.setFieldText("modules", "0,1000,0; 0,2000,0; 0,-3000,0");
    ASSERT_TRUE(panel.composed().has_value()) << panel.problem().toStdString();
    EXPECT_EQ(panel.composed()->bytes, vt::test::hcs_examples::kOpat342Request);

    panel.setKind(ComposeKind::PkwRead); // ED1/SD1 manual §4.6.1 example 2
    panel.setFieldText("ind", "3");
    panel.setFieldText("pnu", "98");
    ASSERT_TRUE(panel.composed().has_value());
    EXPECT_EQ(panel.composed()->bytes,
              (dev::Bytes{0x10, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00}));

    panel.setFieldText("pnu", "seventy");
    EXPECT_FALSE(panel.composed().has_value());
    EXPECT_FALSE(panel.problem().isEmpty());
    EXPECT_FALSE(panel.canSend());
}

TEST(ComposePanel, SendNeedsALinkThatCarriesTheFrame)
{
    ComposePanel panel;
    panel.setKind(ComposeKind::ModbusRead);
    EXPECT_TRUE(panel.sendBlockedReason().contains(QStringLiteral("Not connected")));
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51")); // a single DMA: Modbus RTU
    panel.setConnection(rig.connection.get());
    EXPECT_TRUE(panel.canSend()) << panel.sendBlockedReason().toStdString();
    panel.setKind(ComposeKind::PkwRead);
    EXPECT_TRUE(panel.sendBlockedReason().contains(QStringLiteral("PROFIBUS")));
    panel.setKind(ComposeKind::SdoUpload);
    EXPECT_TRUE(panel.sendBlockedReason().contains(QStringLiteral("modbus-rtu")));
    EXPECT_FALSE(panel.send());
    rig.connection.reset(); // a closed / destroyed connection disables Send
    EXPECT_FALSE(panel.canSend());
}

TEST(ComposePanel, ReadIsSentAndAnswered)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51"));
    ComposePanel panel;
    panel.setConnection(rig.connection.get());
    panel.setKind(ComposeKind::ModbusRead);
    panel.setModbusTcp(false);
    panel.setFieldText("unit", QString::number(rig.connection->moduleAddresses().front()));
    panel.setFieldText("id", "7"); // d1.07
    panel.setFieldText("count", "1");
    QSignalSpy finished(&panel, &ComposePanel::sendFinished);
    ASSERT_TRUE(panel.send());
    ASSERT_TRUE(finished.wait(test::kWaitMs));
    EXPECT_TRUE(finished.at(0).at(1).toBool());
    rig.log->flush();
    ASSERT_GE(rig.log->size(), 2);
    const auto &request = rig.log->at(rig.log->size() - 2);
    const auto &answer = rig.log->at(rig.log->size() - 1);
    EXPECT_EQ(request.direction, dev::Direction::Request);
    EXPECT_EQ(request.bytes, QByteArray::fromHex("01030007000135CB"));
    EXPECT_EQ(answer.direction, dev::Direction::Response);
    EXPECT_EQ(answer.status, model::TelegramRecord::Status::Ok);
    EXPECT_EQ(answer.bytes.at(1), 0x03);
}

// The frame first offered is one the link can send; the answer is decoded, not only hex; a field
// out of range is named as the panel labels it ("Count", not the manual's "N").
TEST(ComposePanel, OffersASendableFrameDecodesTheAnswerAndNamesItsFields)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51")); // a single DMA: Modbus RTU
    ComposePanel panel;
    panel.setKind(ComposeKind::PkwRead); // no link of ValveTune carries it
    panel.setConnection(rig.connection.get());
    EXPECT_EQ(panel.kind(), ComposeKind::ModbusRead);
    EXPECT_TRUE(panel.canSend()) << panel.sendBlockedReason().toStdString();

    panel.setFieldText("id", "7");
    panel.setFieldText("count", "1");
    QSignalSpy finished(&panel, &ComposePanel::sendFinished);
    ASSERT_TRUE(panel.send());
    ASSERT_TRUE(finished.wait(test::kWaitMs));
    const QString text = finished.at(0).at(0).toString();
    EXPECT_TRUE(text.startsWith(QStringLiteral("Answered: FC 3"))) << text.toStdString();
    EXPECT_TRUE(panel.detail()->headline().contains(QStringLiteral("FC 3")))
        << panel.detail()->headline().toStdString();

    panel.setKind(ComposeKind::GatewayRead);
    panel.setFieldText("count", "9"); // OPAT manual §2.1: at most 8
    EXPECT_EQ(panel.problem(), QStringLiteral("Count must be 1 to 8."));
}

TEST(ComposePanel, WritesAskFirst)
{
    QTemporaryDir logDir;
    vt::model::AuditLog audit(QStringLiteral("valvetune"), QStringLiteral("test"), logDir.path());
    const vt::model::AuditLog::Scope auditScope(audit);
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51"));
    ComposePanel panel;
    panel.setConnection(rig.connection.get());
    panel.setKind(ComposeKind::ModbusWrite);
    panel.setFieldText("unit", QString::number(rig.connection->moduleAddresses().front()));
    panel.setFieldText("id", "0x0030"); // C1.07
    panel.setFieldText("value", "1000");
    QStringList asked;
    panel.setConfirmation([&](const QString &q) {
        asked << q;
        return false;
    });
    const qsizetype before = rig.log->size();
    EXPECT_FALSE(panel.send());
    ASSERT_EQ(asked.size(), 1);
    rig.log->flush();
    EXPECT_EQ(rig.log->size(), before);

    panel.setConfirmation([&](const QString &q) {
        asked << q;
        return true;
    });
    QSignalSpy finished(&panel, &ComposePanel::sendFinished);
    ASSERT_TRUE(panel.send());
    ASSERT_TRUE(finished.wait(test::kWaitMs));
    EXPECT_EQ(asked.size(), 2);
    EXPECT_TRUE(finished.at(0).at(1).toBool()) << finished.at(0).at(0).toString().toStdString();
    // The refused question sent nothing and logged nothing; the sent write is in the session log,
    // as its bytes (no module was identified here, so no dictionary names the register).
    const vt::model::AuditLogContents log = vt::model::readAuditLog(audit.path());
    ASSERT_TRUE(log.ok) << log.error.toStdString();
    ASSERT_EQ(log.entries.size(), 1u);
    EXPECT_TRUE(log.entries[0].row.isEmpty());
    EXPECT_TRUE(log.entries[0].newRaw.contains(QStringLiteral("00 30 03 E8")))
        << log.entries[0].newRaw.toStdString(); // register 0x0030 (C1.07) = 1000
    EXPECT_EQ(log.entries[0].status, QStringLiteral("written"));
    EXPECT_EQ(log.entries[0].origin, QStringLiteral("compose"));
}

TEST(ComposePanel, GatewayTelegramGoesOutAsAPaddedNodeImage)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("dma-pn-v51", 3, "node-image"));
    ASSERT_EQ(rig.connection->protocolKey(), QStringLiteral("node-image"));
    ComposePanel panel;
    panel.setConnection(rig.connection.get());
    panel.setKind(ComposeKind::GatewayRead); // DMA Profinet manual §3.7: d1.07 of module 1
    panel.setFieldText("tadr", "0x24");
    panel.setFieldText("sadr", "1");
    panel.setFieldText("id", "7");
    panel.setFieldText("count", "1");
    ASSERT_TRUE(panel.canSend()) << panel.sendBlockedReason().toStdString();
    QSignalSpy finished(&panel, &ComposePanel::sendFinished);
    ASSERT_TRUE(panel.send());
    ASSERT_TRUE(finished.wait(test::kWaitMs));
    EXPECT_TRUE(finished.at(0).at(1).toBool()) << finished.at(0).at(0).toString().toStdString();
    rig.log->flush();
    ASSERT_GE(rig.log->size(), 2);
    const auto &request = rig.log->at(rig.log->size() - 2);
    EXPECT_EQ(request.bytes.size(), 42); // the node's output image (§4.5.4)
    EXPECT_EQ(request.bytes.left(7), QByteArray::fromHex("24010300070001"));
    const auto &answer = rig.log->at(rig.log->size() - 1);
    EXPECT_EQ(answer.direction, dev::Direction::Response);
    EXPECT_EQ(answer.bytes.left(4), QByteArray::fromHex("24010302")); // TADR SADR CMD CNT
}

TEST(ComposePanel, HartCommandZeroIsAnsweredByTheSd7)
{
    test::LoggedSim rig;
    ASSERT_TRUE(rig.open("wandfluh-sd7"));
    ComposePanel panel;
    panel.setConnection(rig.connection.get());
    panel.setKind(ComposeKind::HartCommand); // HART-7 manual §2.3: command 0, short frame
    panel.setFieldText("poll", "0");
    panel.setFieldText("deviceType", "");
    panel.setFieldText("command", "0");
    panel.setFieldText("data", "");
    ASSERT_TRUE(panel.canSend()) << panel.sendBlockedReason().toStdString();
    EXPECT_FALSE(panel.composed()->writes);
    QSignalSpy finished(&panel, &ComposePanel::sendFinished);
    ASSERT_TRUE(panel.send());
    ASSERT_TRUE(finished.wait(test::kWaitMs));
    EXPECT_TRUE(finished.at(0).at(1).toBool()) << finished.at(0).at(0).toString().toStdString();
}
