#include "hex_view.h"

#include <QFontDatabase>
#include <QMouseEvent>
#include <QPainter>

namespace vt::ui {
namespace {
constexpr int kMargin = 4;
}

HexView::HexView(QWidget *parent) : QWidget(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setFocusPolicy(Qt::ClickFocus);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
}

void HexView::setBytes(const QByteArray &bytes)
{
    m_bytes = bytes;
    m_highlightOffset = 0;
    m_highlightLength = 0;
    m_errorOffset = -1;
    updateGeometry();
    update();
}

void HexView::setHighlight(int offset, int length)
{
    m_highlightOffset = std::max(0, offset);
    m_highlightLength = std::max(0, length);
    update();
}

void HexView::setErrorOffset(int offset)
{
    m_errorOffset = offset;
    update();
}

int HexView::rowCount() const
{
    return std::max<int>(1, static_cast<int>((m_bytes.size() + kBytesPerRow - 1) / kBytesPerRow));
}

int HexView::cellWidth() const
{
    return fontMetrics().horizontalAdvance(QStringLiteral("00 "));
}

int HexView::rowHeight() const
{
    return fontMetrics().height() + 2;
}

int HexView::offsetWidth() const
{
    return fontMetrics().horizontalAdvance(QStringLiteral("0000  "));
}

int HexView::asciiLeft() const
{
    return kMargin + offsetWidth() + kBytesPerRow * cellWidth() + cellWidth() / 2;
}

QRect HexView::byteRect(int offset) const
{
    if (offset < 0 || offset >= m_bytes.size())
        return {};
    const int row = offset / kBytesPerRow;
    const int col = offset % kBytesPerRow;
    return QRect(kMargin + offsetWidth() + col * cellWidth(), kMargin + row * rowHeight(),
                 cellWidth(), rowHeight());
}

int HexView::byteAt(const QPoint &pos) const
{
    const int row = (pos.y() - kMargin) / rowHeight();
    if (pos.y() < kMargin || row >= rowCount())
        return -1;
    int col = -1;
    const int hexLeft = kMargin + offsetWidth();
    const int charWidth = fontMetrics().horizontalAdvance(QLatin1Char('0'));
    if (pos.x() >= hexLeft && pos.x() < hexLeft + kBytesPerRow * cellWidth())
        col = (pos.x() - hexLeft) / cellWidth();
    else if (pos.x() >= asciiLeft() && pos.x() < asciiLeft() + kBytesPerRow * charWidth)
        col = (pos.x() - asciiLeft()) / charWidth; // the character column maps to its byte too
    const int offset = row * kBytesPerRow + col;
    return col < 0 || offset >= m_bytes.size() ? -1 : offset;
}

QSize HexView::sizeHint() const
{
    const int charWidth = fontMetrics().horizontalAdvance(QLatin1Char('0'));
    return QSize(asciiLeft() + kBytesPerRow * charWidth + kMargin,
                 2 * kMargin + rowCount() * rowHeight());
}

QSize HexView::minimumSizeHint() const
{
    return QSize(sizeHint().width(), 2 * kMargin + rowHeight());
}

void HexView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    const QColor highlight = palette().highlight().color();
    const QColor highlightText = palette().highlightedText().color();
    const QColor errorColour(200, 30, 30);
    const int charWidth = fontMetrics().horizontalAdvance(QLatin1Char('0'));
    const int ascent = fontMetrics().ascent() + 1;
    for (int row = 0; row < rowCount(); ++row) {
        const int y = kMargin + row * rowHeight();
        p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
        p.drawText(kMargin, y + ascent,
                   QStringLiteral("%1").arg(row * kBytesPerRow, 4, 16, QLatin1Char('0')).toUpper());
        for (int col = 0; col < kBytesPerRow; ++col) {
            const int offset = row * kBytesPerRow + col;
            if (offset >= m_bytes.size())
                break;
            const auto byte = static_cast<unsigned char>(m_bytes.at(offset));
            const QRect cell = byteRect(offset);
            const QRect charCell(asciiLeft() + col * charWidth, y, charWidth, rowHeight());
            const bool selected =
                offset >= m_highlightOffset && offset < m_highlightOffset + m_highlightLength;
            QColor text = palette().text().color();
            if (selected) {
                p.fillRect(cell.adjusted(0, 0, -charWidth / 2, 0), highlight);
                p.fillRect(charCell, highlight);
                text = highlightText;
            }
            if (offset == m_errorOffset) {
                p.setPen(errorColour);
                p.drawRect(cell.adjusted(0, 0, -charWidth / 2 - 1, -1));
                if (!selected)
                    text = errorColour;
            }
            p.setPen(text);
            p.drawText(cell.left(), y + ascent,
                       QStringLiteral("%1").arg(byte, 2, 16, QLatin1Char('0')).toUpper());
            p.drawText(charCell.left(), y + ascent,
                       byte >= 0x20 && byte < 0x7F ? QString(QLatin1Char(static_cast<char>(byte)))
                                                   : QStringLiteral("·"));
        }
    }
}

void HexView::mousePressEvent(QMouseEvent *event)
{
    const int offset = byteAt(event->position().toPoint());
    if (offset >= 0)
        emit byteClicked(offset);
    QWidget::mousePressEvent(event);
}

void HexView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange)
        updateGeometry();
    QWidget::changeEvent(event);
}

} // namespace vt::ui
