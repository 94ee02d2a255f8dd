// The decode box ("each worked example of the manuals pasted in decodes to the
// right fields and highlights the right bytes; a corrupted frame shows its error without
// crashing"). Byte strings are the codec tests' worked examples, cited by manual section.
#include "dict/dictionary_loader.h"
#include "hcs/worked_examples.h"
#include "model/inspect/field_tree_model.h"
#include "profidrive/worked_examples.h"
#include "widgets/inspector/decode_panel.h"
#include "widgets/inspector/frame_detail.h"
#include "widgets/inspector/hex_view.h"

#include <QCoreApplication>
#include <QTest>
#include <QTreeView>
#include <gtest/gtest.h>

using namespace vt;
using vt::dev::Direction;
using vt::dev::FrameFormat;
using vt::ui::DecodePanel;

namespace {

QString hexOf(const dev::Bytes &b)
{
    QString s;
    for (auto x : b)
        s += QStringLiteral("%1 ").arg(x, 2, 16, QLatin1Char('0'));
    return s;
}

// Selects the field in the tree and returns the hex view's highlighted range.
std::pair<int, int> highlightOf(DecodePanel &panel, const QString &key)
{
    EXPECT_TRUE(panel.detail()->selectField(key)) << key.toStdString();
    const ui::HexView *hex = panel.detail()->hexView();
    return {hex->highlightOffset(), hex->highlightLength()};
}

struct Case
{
    const char *section;
    dev::Bytes bytes;
    std::optional<FrameFormat> protocol; // nullopt = auto
    Direction direction;
    const char *key;
    int offset, length;
    const char *value;
};

} // namespace

TEST(DecodePanel, WorkedExamplesDecodeAndHighlightTheirFields)
{
    using namespace vt::test::hcs_examples;
    using namespace vt::test::profidrive_examples;
    const Case examples[] = {
        {"OPAT §2.7 CMD 6", kOpat27Write, std::nullopt, Direction::Request, "ID", 3, 2, "0x0030"},
        {"OPAT §2.7 CMD 6 value", kOpat27Write, std::nullopt, Direction::Request, "DAT", 5, 2,
         "1000"},
        {"DMA §3.7 CMD 3 answer", kDma37ReadResponse, std::nullopt, Direction::Response, "CNT", 3,
         1, "2"},
        {"OPAT §2.3 error", kOpat23ReadError, FrameFormat::Gateway, Direction::Response, "EXCE", 3,
         1, "5"},
        {"OPAT §3.4.2 CMD 15", kOpat342Request, std::nullopt, Direction::Request, "SNUM", 1, 1,
         "2"},
        {"OPAT §5.6 PROFIdrive + CMD 15", kSec56Request, std::nullopt, Direction::Request, "STW1",
         0, 2, nullptr},
        {"ED1/SD1 §4.6.1 ex. 1 PKW",
         {0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2},
         FrameFormat::Pkw,
         Direction::Request,
         "pkw.pnu",
         0,
         2,
         "73"},
        {"HART-7 §4.4.1 ex. 1",
         {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x82, 0xA3, 0xF0, 0x12, 0x34, 0x56, 0x83, 0x05, 0xFA, 0x06,
          0x00, 0x01, 0xC2, 0x18},
         std::nullopt,
         Direction::Request,
         "hart.param.value",
         16,
         2,
         "450 (0x01C2)"},
        {"CiA 301 expedited download",
         {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00},
         FrameFormat::Canopen,
         Direction::Request,
         "sdo.index",
         1,
         2,
         "0x6040"},
    };
    DecodePanel panel;
    panel.resize(900, 600);
    panel.show();
    for (const Case &e : examples) {
        SCOPED_TRACE(e.section);
        panel.setFamily(std::string(e.section).rfind("DMA", 0) == 0 ? dev::hcs::Family::Dma
                                                                    : dev::hcs::Family::Opat);
        panel.setDirection(e.direction);
        panel.setProtocol(e.protocol);
        panel.setText(hexOf(e.bytes));
        ASSERT_TRUE(panel.decodedProtocol().has_value()) << panel.statusText().toStdString();
        EXPECT_TRUE(panel.description().ok()) << panel.detail()->headline().toStdString();
        const dev::FieldSpan *f = panel.description().field(e.key);
        ASSERT_NE(f, nullptr) << e.key;
        EXPECT_EQ(static_cast<int>(f->offset), e.offset);
        EXPECT_EQ(static_cast<int>(f->length), e.length);
        if (e.value) {
            EXPECT_EQ(f->value, e.value);
        }
        EXPECT_EQ(highlightOf(panel, QString::fromLatin1(e.key)),
                  std::make_pair(e.offset, e.length));
    }
}

TEST(DecodePanel, ClickingAByteSelectsTheDeepestField)
{
    DecodePanel panel;
    panel.resize(900, 600);
    panel.show();
    panel.setFamily(dev::hcs::Family::Opat);
    panel.setText(QStringLiteral("0x23,0x00,0x06,0x00,0x30,0x03,0xE8")); // OPAT manual §2.7
    ui::HexView *hex = panel.detail()->hexView();
    QTest::mouseClick(hex, Qt::LeftButton, {}, hex->byteRect(4).center());
    EXPECT_EQ(panel.detail()->selectedKey(), QStringLiteral("ID"));
    EXPECT_EQ(hex->highlightOffset(), 3);
    EXPECT_EQ(hex->highlightLength(), 2);
    QTest::mouseClick(hex, Qt::LeftButton, {}, hex->byteRect(0).center());
    EXPECT_EQ(panel.detail()->selectedKey(), QStringLiteral("TADR"));
}

TEST(DecodePanel, DictionaryNamesParameters)
{
    DecodePanel panel;
    const auto &set = *dev::builtinDictionaries();
    panel.setDictionary(set.find("opat"));
    panel.setFamily(dev::hcs::Family::Opat);
    panel.setText(QStringLiteral("23 00 06 00 30 03 E8"));
    const dev::FieldSpan *id = panel.description().field("ID");
    ASSERT_NE(id, nullptr);
    EXPECT_NE(id->text.en.find("C1.07"), std::string::npos);
}

TEST(DecodePanel, CorruptedFramesShowTheirErrorWithoutCrashing)
{
    DecodePanel panel;
    panel.resize(900, 600);
    panel.show();
    // Modbus RTU with a broken CRC (Modbus over Serial Line §2.5.1.2).
    panel.setProtocol(FrameFormat::ModbusRtu);
    panel.setText(QStringLiteral("01 03 00 07 00 01 35 CC"));
    ASSERT_FALSE(panel.description().ok());
    EXPECT_EQ(panel.description().error->code, dev::DecodeErrc::BadChecksum);
    EXPECT_TRUE(panel.detail()->headline().contains(QStringLiteral("byte 6")));
    // The byte is named once ("Error at byte 6: checksum error: CRC …").
    EXPECT_EQ(panel.detail()->headline().count(QStringLiteral("byte 6")), 1)
        << panel.detail()->headline().toStdString();
    EXPECT_EQ(panel.detail()->hexView()->errorOffset(), 6);
    // A truncated CMD 6 (OPAT manual §2.4 needs 7 bytes).
    panel.setProtocol(FrameFormat::Gateway);
    panel.setText(QStringLiteral("23 00 06 00 30"));
    ASSERT_FALSE(panel.description().ok());
    EXPECT_EQ(panel.description().error->code, dev::DecodeErrc::Truncated);
    // Not hex at all, and far too long.
    panel.setText(QStringLiteral("23 zz"));
    EXPECT_FALSE(panel.decodedProtocol().has_value());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("4")));
    panel.setText(QString(70'000, QLatin1Char('0')));
    EXPECT_FALSE(panel.decodedProtocol().has_value());
}

TEST(DecodePanel, AutoSaysWhenItCannotDecide)
{
    DecodePanel panel;
    panel.setProtocol(std::nullopt);
    // ED1/SD1 manual §4.6.1 example 1: PKW or an SDO — auto does not guess.
    panel.setText(QStringLiteral("20 49 03 00 00 00 01 C2"));
    EXPECT_FALSE(panel.decodedProtocol().has_value());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("pkw")));
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("canopen")));
    // A candump frame is unambiguous.
    panel.setText(QStringLiteral("605#2B4060000F000000"));
    ASSERT_TRUE(panel.decodedProtocol().has_value());
    EXPECT_EQ(*panel.decodedProtocol(), FrameFormat::Canopen);
    // A Modbus RTU answer: auto picks the response direction by itself.
    panel.setDirection(Direction::Request);
    panel.setText(QStringLiteral("01 83 02 C0 F1"));
    ASSERT_TRUE(panel.decodedProtocol().has_value());
    EXPECT_EQ(*panel.decodedProtocol(), FrameFormat::ModbusRtu);
    EXPECT_TRUE(panel.description().ok());
    // A Modbus RTU read with a wrong CRC is named as one, not left undecided.
    panel.setText(QStringLiteral("01 03 00 07 00 01 35 34"));
    ASSERT_TRUE(panel.decodedProtocol().has_value()) << panel.statusText().toStdString();
    EXPECT_EQ(*panel.decodedProtocol(), FrameFormat::ModbusRtu);
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("CRC")))
        << panel.statusText().toStdString();
    EXPECT_EQ(panel.description().error->code, dev::DecodeErrc::BadChecksum);
}

TEST(DecodePanel, LanguageChangeSwitchesTheCoreTexts)
{
    DecodePanel panel;
    panel.setFamily(dev::hcs::Family::Opat);
    panel.setText(QStringLiteral("23 00 06 00 30 03 E8")); // OPAT manual §2.7
    auto *model = panel.detail()->fieldModel();
    const QModelIndex cmd = model->indexForKey(QStringLiteral("CMD"));
    const QModelIndex meaning = cmd.siblingAtColumn(model::FieldTreeModel::MeaningColumn);
    const QString english = meaning.data().toString();
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(panel.detail(), &change);
    const QString german = meaning.data().toString();
    QLocale::setDefault(before);
    EXPECT_NE(english, german);
    EXPECT_TRUE(german.contains(QStringLiteral("Schreiben"))) << german.toStdString();
}

TEST(DecodePanel, AutoPrefersTheFamilyTheSnumFitsOverPadding)
{
    DecodePanel panel;
    panel.setFamily(dev::hcs::Family::Dma);
    panel.setProtocol(std::nullopt);
    // OPAT manual §3.4.2: SNUM 2 = master + 2 slaves (18 bytes). As DMA it would be 2 modules and
    // 5 bytes of padding; the exact OPAT reading wins.
    panel.setText(hexOf(vt::test::hcs_examples::kOpat342Request));
    ASSERT_TRUE(panel.description().ok());
    EXPECT_NE(panel.description().field("DAT0"), nullptr); // the OPAT master, SADR 0
    EXPECT_NE(panel.description().field("DAT2"), nullptr);
    EXPECT_EQ(panel.description().field("padding"), nullptr);
    // A 42-byte process image still decodes, with its padding shown.
    dev::Bytes image = vt::test::hcs_examples::kDma37Write;
    image.resize(42, 0);
    panel.setText(hexOf(image));
    ASSERT_TRUE(panel.description().ok()) << panel.statusText().toStdString();
    EXPECT_NE(panel.description().field("padding"), nullptr);
}
