// Linked navigation over a TelegramLog of Modbus RTU, node-image and CANopen records.
#include "canopen/can_frame.h"
#include "dict/dictionary_loader.h"
#include "hcs/worked_examples.h"
#include "model/inspect/frame_links.h"

#include <gtest/gtest.h>

using namespace vt;
using vt::dev::Direction;

namespace {

const dev::Dictionary &dma()
{
    return *dev::builtinDictionaries()->find("dma-pn-v51");
}

QByteArray qt(const dev::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), static_cast<qsizetype>(b.size()));
}

} // namespace

TEST(FrameLinks, ParameterToItsLastExchangeAndBack)
{
    model::TelegramLog log;
    const QString link = QStringLiteral("sim");
    // Modbus RTU FC 3 of d1.07 (ID 7) at unit 1, twice; FC 6 of C1.07 (ID 0x30) at unit 2.
    const dev::Bytes read7{0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x35, 0xCB};
    const quint64 first = log.append(Direction::Request, link, "modbus-rtu", 1, qt(read7));
    log.append(Direction::Response, link, "modbus-rtu", 1, QByteArray::fromHex("010302013339D0"));
    const quint64 again = log.append(Direction::Request, link, "modbus-rtu", 1, qt(read7));
    const quint64 timeout = log.appendTimeout(link, "modbus-rtu", 1);
    const quint64 answer = log.append(Direction::Response, link, "modbus-rtu", 1,
                                      QByteArray::fromHex("010302013339D0"));
    log.append(Direction::Request, link, "modbus-rtu", 2, QByteArray::fromHex("0206003003E8"));
    // Node image (DMA Profinet manual §3.7 padded to 42 bytes) for C1.07 at SADR 1.
    dev::Bytes image = vt::test::hcs_examples::kDma37Write;
    image.resize(42, 0);
    const quint64 nodeWrite = log.append(Direction::Request, link, "node-image", 1, qt(image));
    // CANopen upload of 0x2007 (HCS ID 7) from node 3.
    const auto sdo = dev::canopen::toSocketCan(
        dev::canopen::makeCanFrame(0x603, dev::Bytes{0x40, 0x07, 0x20, 0, 0, 0, 0, 0}));
    const quint64 can =
        log.append(Direction::Request, link, "canopen", 3, qt(dev::Bytes(sdo.begin(), sdo.end())));

    EXPECT_EQ(model::lastFramesFor(log, 1, "d1.07", dma()),
              (QList<quint64>{again, timeout, answer}));
    EXPECT_EQ(model::lastFramesFor(log, 1, "C1.07", dma()), (QList<quint64>{nodeWrite}));
    EXPECT_EQ(model::lastFramesFor(log, 3, "d1.07", dma()), (QList<quint64>{can}));
    EXPECT_EQ(model::lastFramesFor(log, -1, "d1.07", dma()), (QList<quint64>{can}));
    EXPECT_TRUE(model::lastFramesFor(log, 2, "d1.07", dma()).isEmpty());

    EXPECT_EQ(model::parametersOfRecord(log, first, dma()), QStringList{"d1.07"});
    EXPECT_EQ(model::parametersOfRecord(log, answer, dma()),
              QStringList{"d1.07"}); // via its request
    EXPECT_EQ(model::parametersOfRecord(log, nodeWrite, dma()), QStringList{"C1.07"});
    EXPECT_EQ(model::requestSeqOf(log, timeout), again);
}

TEST(FrameLinks, ReadBlocksNameEveryParameter)
{
    model::TelegramLog log;
    // OPAT manual §2.1 style block read: IDs 7..9 at SADR 1.
    const quint64 seq = log.append(Direction::Request, "sim", "node-image", 1,
                                   QByteArray::fromHex("24010300070003"));
    EXPECT_EQ(model::parametersOfRecord(log, seq, dma()), (QStringList{"d1.07", "d1.08", "d1.09"}));
    EXPECT_FALSE(model::requestSeqOf(log, 999).has_value());
}
