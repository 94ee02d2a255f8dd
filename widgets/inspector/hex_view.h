// HexView: a frame's bytes as a hex dump (offset, 16 bytes a row) that highlights one field's
// byte range and reports clicks on a byte, for the inspector's detail pane. Paints itself;
// put it in a QScrollArea for long frames.
#pragma once

#include <QByteArray>
#include <QWidget>

namespace vt::ui {

class HexView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kBytesPerRow = 16;

    explicit HexView(QWidget *parent = nullptr);

    void setBytes(const QByteArray &bytes);
    QByteArray bytes() const { return m_bytes; }
    // The selected field's bytes; length 0 clears. Clipped to the frame when painted.
    void setHighlight(int offset, int length);
    int highlightOffset() const { return m_highlightOffset; }
    int highlightLength() const { return m_highlightLength; }
    // The byte where decoding failed (painted in the error colour); -1 = none.
    void setErrorOffset(int offset);
    int errorOffset() const { return m_errorOffset; }

    // Geometry, for clicks and tests: the cell of a byte, the byte under a point (-1 = none).
    QRect byteRect(int offset) const;
    int byteAt(const QPoint &pos) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void byteClicked(int offset);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    int rowCount() const;
    int cellWidth() const;
    int rowHeight() const;
    int offsetWidth() const;
    int asciiLeft() const;

    QByteArray m_bytes;
    int m_highlightOffset = 0;
    int m_highlightLength = 0;
    int m_errorOffset = -1;
};

} // namespace vt::ui
