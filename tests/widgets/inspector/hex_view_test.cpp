// HexView: byte cells, clicks on the hex and the character columns, and
// the highlighted range.
#include "widgets/inspector/hex_view.h"

#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>

using vt::ui::HexView;

TEST(HexView, ClickReportsTheByteUnderTheMouse)
{
    HexView view;
    QByteArray bytes;
    for (int i = 0; i < 40; ++i)
        bytes.append(static_cast<char>(i));
    view.setBytes(bytes);
    view.resize(view.sizeHint());
    view.show();
    QSignalSpy spy(&view, &HexView::byteClicked);
    for (int offset : {0, 5, 15, 16, 39}) {
        const QRect cell = view.byteRect(offset);
        ASSERT_TRUE(cell.isValid()) << offset;
        EXPECT_EQ(view.byteAt(cell.center()), offset);
        QTest::mouseClick(&view, Qt::LeftButton, {}, cell.center());
        ASSERT_FALSE(spy.isEmpty());
        EXPECT_EQ(spy.takeLast().at(0).toInt(), offset);
    }
    EXPECT_FALSE(view.byteRect(40).isValid());
    // Past the last byte of the last row: nothing.
    const QRect last = view.byteRect(39);
    EXPECT_EQ(view.byteAt(last.center() + QPoint(3 * last.width(), 0)), -1);
}

TEST(HexView, HighlightAndErrorAreKeptUntilNewBytes)
{
    HexView view;
    view.setBytes(QByteArray::fromHex("2300060030 03E8"));
    view.setHighlight(3, 2);
    view.setErrorOffset(6);
    EXPECT_EQ(view.highlightOffset(), 3);
    EXPECT_EQ(view.highlightLength(), 2);
    EXPECT_EQ(view.errorOffset(), 6);
    view.resize(view.sizeHint());
    view.show();
    view.repaint(); // paints without trouble
    view.setBytes(QByteArray::fromHex("01"));
    EXPECT_EQ(view.highlightLength(), 0);
    EXPECT_EQ(view.errorOffset(), -1);
}
