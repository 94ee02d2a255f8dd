// FrameDetail: one frame explained — its summary or error, the field tree of its description and
// its hex dump; selecting a field highlights its bytes, clicking a byte selects the deepest field
// covering it. Shared by the list's detail pane, the decode box and the composer's preview.
#pragma once

#include "core/field_span.h"

#include <QByteArray>
#include <QWidget>

class QLabel;
class QTreeView;

namespace vt::model {
class FieldTreeModel;
}

namespace vt::ui {

class HexView;

class FrameDetail : public QWidget
{
    Q_OBJECT
public:
    explicit FrameDetail(QWidget *parent = nullptr);

    void setFrame(const QByteArray &bytes, const vt::dev::Description &description);
    // A record without a description (a timeout, an unknown protocol): the bytes and a note.
    void setUndescribed(const QByteArray &bytes, const QString &note);
    void clear();

    // Selects the field with this key (its bytes light up); false when the frame has none.
    bool selectField(const QString &key);
    QString selectedKey() const;

    QString headline() const; // the summary / error line as shown
    HexView *hexView() const { return m_hex; }
    QTreeView *treeView() const { return m_tree; }
    vt::model::FieldTreeModel *fieldModel() const { return m_model; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void onCurrentChanged();
    void onByteClicked(int offset);
    void updateHeadline();

    vt::model::FieldTreeModel *m_model;
    QLabel *m_headline;
    QTreeView *m_tree;
    HexView *m_hex;
    QString m_note; // setUndescribed()
};

} // namespace vt::ui
