#include "lcurve_editor.h"

#include "lcurve_delegate.h"
#include "lcurve_plot.h"
#include "model/curve/lcurve_table_model.h"
#include "model/text_language.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace vt::ui {

LCurveEditor::LCurveEditor(QWidget *parent) : QWidget(parent)
{
    m_plot = new LCurvePlot(this);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("curveTable"));
    auto *delegate = new LCurveDelegate(m_table);
    m_table->setItemDelegate(delegate);
    connect(delegate, &LCurveDelegate::refused, this,
            [this](const QString &reason) { m_message->setText(reason); });
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The table is as wide as its columns; the plot takes the rest.
    m_table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_table->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Expanding);
    m_plot->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);

    // The branch chosen in the table is the one a drag grabs where both curves overlap.
    connect(m_table, &QTableView::clicked, this, [this](const QModelIndex &index) {
        if (m_model)
            m_plot->setPreferredCurve(m_model->curveOfColumn(index.column()));
    });
    connect(m_plot, &LCurvePlot::pointPicked, this, [this](int curve, int index) {
        if (m_model)
            m_table->setCurrentIndex(m_model->indexOf(curve, index, model::LAxis::Y));
    });

    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setObjectName(QStringLiteral("curveSplitter"));
    splitter->addWidget(m_plot);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 0);
    splitter->setChildrenCollapsible(false);

    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("refusal"));
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText);
    QPalette warn = m_message->palette();
    warn.setColor(QPalette::WindowText, QColor(180, 0, 0));
    m_message->setPalette(warn);

    m_noCurve = new QLabel(this);
    m_noCurve->setObjectName(QStringLiteral("noCurve"));
    m_noCurve->setWordWrap(true);
    m_noCurve->setAlignment(Qt::AlignCenter);
    m_noCurve->setVisible(false);
    m_views = splitter;

    m_subject = new QLabel(this);
    m_subject->setObjectName(QStringLiteral("curveModule"));
    QFont bold = m_subject->font();
    bold.setBold(true);
    m_subject->setFont(bold);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_subject);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_noCurve, 1);
    layout->addWidget(m_hint);
    layout->addWidget(m_message);
    retranslate();
}

void LCurveEditor::setModel(model::LCurveTableModel *model)
{
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    m_plot->setModel(model);
    m_table->setModel(model);
    m_message->clear();
    if (model) {
        connect(model, &model::LCurveTableModel::editRefused, this, &LCurveEditor::showRefusal);
        connect(model, &model::LCurveTableModel::rowsEdited, m_message, &QLabel::clear);
        connect(model, &QAbstractItemModel::modelReset, this, &LCurveEditor::showWhetherCurves);
        connect(model, &QObject::destroyed, this, [this] {
            m_model = nullptr;
            showWhetherCurves();
        });
    }
    showWhetherCurves();
}

QString LCurveEditor::noCurveText() const
{
    return m_noCurve->isVisibleTo(this) ? m_noCurve->text() : QString();
}

void LCurveEditor::showWhetherCurves()
{
    // The DMA-2 PROFIBUS lists and the Wandfluh profiles have no L block: an empty plot with
    // the DMA help under it would suggest a curve that is not there.
    const dev::Dictionary *dictionary = m_model ? m_model->dictionary() : nullptr;
    const bool none = dictionary && m_model->curves().empty();
    if (none)
        m_noCurve->setText(
            tr("This device has no linearisation curve: the parameter list of %1 has no L block.")
                .arg(QString::fromStdString(dictionary->title.in(model::textLanguage()))));
    m_noCurve->setVisible(none);
    m_views->setVisible(!none);
    m_hint->setVisible(!none);
    // The table as wide as its columns: the splitter sizes it by its minimum, not its hint.
    int width = m_table->verticalHeader()->sizeHint().width() + 2 * m_table->frameWidth() +
                m_table->verticalScrollBar()->sizeHint().width() + 4;
    const QAbstractItemView *view = m_table; // sizeHintForColumn is public here
    for (int c = 0; m_model && c < m_model->columnCount(); ++c)
        width += qMax(view->sizeHintForColumn(c), m_table->horizontalHeader()->sectionSizeHint(c));
    m_table->setMinimumWidth(width);
}

void LCurveEditor::setModule(int address)
{
    m_address = address;
    retranslate();
}

QString LCurveEditor::moduleText() const
{
    return m_subject->text();
}

QString LCurveEditor::message() const
{
    return m_message->text();
}

void LCurveEditor::showRefusal(int, int, const QString &reason)
{
    m_message->setText(reason);
}

void LCurveEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void LCurveEditor::retranslate()
{
    if (m_model)
        m_model->retranslate();
    if (m_noCurve)
        showWhetherCurves();
    m_hint->setText(
        tr("Drag a point or type its coordinates. Input x must rise from point to "
           "point; grey coordinates are fixed by the device. Whether the module applies "
           "the curve depends on the branch's Linearization parameter (C1.02 / C2.02)."));
    if (!m_subject)
        return;
    const dev::Dictionary *dictionary = m_model ? m_model->dictionary() : nullptr;
    m_subject->setText(m_address < 0 ? tr("No module chosen: choose one in the node view.")
                       : !dictionary ? tr("Module %1").arg(m_address)
                                     : tr("Module %1: %2")
                                           .arg(m_address)
                                           .arg(QString::fromStdString(
                                               dictionary->title.in(model::textLanguage()))));
}

} // namespace vt::ui
