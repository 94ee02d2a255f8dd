#include "frame_detail.h"

#include "hex_view.h"
#include "model/inspect/field_tree_model.h"
#include "model/text_language.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QScrollArea>
#include <QSplitter>
#include <QTreeView>
#include <QVBoxLayout>
#include <string>
#include <utility>

namespace vt::ui {

FrameDetail::FrameDetail(QWidget *parent)
    : QWidget(parent), m_model(new vt::model::FieldTreeModel(this)), m_headline(new QLabel(this)),
      m_tree(new QTreeView(this)), m_hex(new HexView(this))
{
    m_headline->setWordWrap(true);
    m_headline->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_tree->setModel(m_model);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->header()->setStretchLastSection(true);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setSelectionBehavior(QAbstractItemView::SelectRows);
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(m_hex);
    scroll->setWidgetResizable(true);
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_tree);
    split->addWidget(scroll);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_headline);
    layout->addWidget(split, 1);

    connect(m_tree->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &FrameDetail::onCurrentChanged);
    connect(m_hex, &HexView::byteClicked, this, &FrameDetail::onByteClicked);
    m_model->setLanguage(model::textLanguage());
}

void FrameDetail::setFrame(const QByteArray &bytes, const vt::dev::Description &description)
{
    m_note.clear();
    m_model->setLanguage(model::textLanguage());
    m_model->setDescription(description);
    m_tree->expandAll();
    for (int c = 0; c < vt::model::FieldTreeModel::MeaningColumn; ++c)
        m_tree->resizeColumnToContents(c);
    m_hex->setBytes(bytes);
    m_hex->setErrorOffset(description.error ? static_cast<int>(description.error->offset) : -1);
    updateHeadline();
}

void FrameDetail::setUndescribed(const QByteArray &bytes, const QString &note)
{
    m_model->clear();
    m_hex->setBytes(bytes);
    m_note = note;
    updateHeadline();
}

void FrameDetail::clear()
{
    setUndescribed({}, {});
}

bool FrameDetail::selectField(const QString &key)
{
    const QModelIndex index = m_model->indexForKey(key);
    if (!index.isValid())
        return false;
    m_tree->setCurrentIndex(index);
    return true;
}

QString FrameDetail::selectedKey() const
{
    return m_tree->currentIndex().data(vt::model::FieldTreeModel::KeyRole).toString();
}

QString FrameDetail::headline() const
{
    return m_headline->text();
}

void FrameDetail::updateHeadline()
{
    const vt::dev::Description &d = m_model->description();
    if (!m_note.isEmpty() || (d.fields.empty() && !d.error)) {
        m_headline->setStyleSheet({});
        m_headline->setText(m_note);
        return;
    }
    if (d.error) {
        m_headline->setStyleSheet(QStringLiteral("color: #c81e1e;"));
        // The headline names the byte; the codec's sentence does not say it a second time.
        vt::dev::LocalText reason = vt::dev::describeError(*d.error);
        const std::string at = std::to_string(d.error->offset);
        const std::pair<std::string *, std::string> said[] = {{&reason.en, " at byte " + at},
                                                              {&reason.de, " bei Byte " + at}};
        for (const auto &[text, words] : said)
            if (const auto i = text->find(words); i != std::string::npos)
                text->erase(i, words.size());
        m_headline->setText(tr("Error at byte %1: %2")
                                .arg(QLocale().toString(static_cast<qulonglong>(d.error->offset)),
                                     model::localText(reason)));
        return;
    }
    m_headline->setStyleSheet({});
    m_headline->setText(model::localText(d.summary));
}

void FrameDetail::onCurrentChanged()
{
    const QModelIndex current = m_tree->currentIndex();
    const vt::dev::FieldSpan *f = m_model->fieldAt(current);
    if (!f) {
        m_hex->setHighlight(0, 0);
        return;
    }
    m_hex->setHighlight(static_cast<int>(f->offset), static_cast<int>(f->length));
}

void FrameDetail::onByteClicked(int offset)
{
    const QModelIndex index = m_model->indexForByte(offset);
    if (!index.isValid())
        return;
    m_tree->scrollTo(index);
    m_tree->setCurrentIndex(index);
}

void FrameDetail::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_model->setLanguage(model::textLanguage());
        updateHeadline();
    }
    QWidget::changeEvent(event);
}

} // namespace vt::ui
