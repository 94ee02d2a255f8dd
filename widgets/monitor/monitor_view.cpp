#include "monitor_view.h"

#include "channel_chooser.h"
#include "model/monitor/monitor_export.h"
#include "model/session/connection.h"
#include "model/text_language.h"
#include "monitor_plot.h"
#include "step_control.h"
#include "widgets/number_box.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

namespace vt::ui {

namespace {

enum ExportKind { CsvVisible, CsvAll, Png, Pdf };
constexpr double kDefaultRateHz = 50;
constexpr double kDefaultWindowS = 10;
constexpr qint64 kFailureRepeatMs = 5000;

} // namespace

MonitorView::MonitorView(QWidget *parent)
    : QWidget(parent), m_session(new model::MonitorSession(this))
{
    m_run = new QPushButton(this);
    m_run->setObjectName(QStringLiteral("monitorRun"));
    m_run->setCheckable(true);
    m_rateLabel = new QLabel(this);
    m_rate = new NumberBox(this);
    m_rate->setRange(0, 1000);
    m_rate->setDecimals(1);
    m_rate->setKeyboardTracking(false);
    m_rate->setValue(kDefaultRateHz);
    m_achieved = new QLabel(this);
    m_windowLabel = new QLabel(this);
    m_window = new NumberBox(this);
    m_window->setRange(0.1, 3600);
    m_window->setDecimals(1);
    m_window->setKeyboardTracking(false);
    m_window->setValue(kDefaultWindowS);
    m_follow = new QCheckBox(this);
    m_follow->setChecked(true);
    m_channels = new QPushButton(this);
    m_clear = new QPushButton(this);
    m_export = new QToolButton(this);
    m_export->setPopupMode(QToolButton::InstantPopup);
    auto *menu = new QMenu(m_export);
    m_exportVisible = menu->addAction(QString(), this, [this] { exportWithDialog(CsvVisible); });
    m_exportAll = menu->addAction(QString(), this, [this] { exportWithDialog(CsvAll); });
    menu->addSeparator();
    m_exportPng = menu->addAction(QString(), this, [this] { exportWithDialog(Png); });
    m_exportPdf = menu->addAction(QString(), this, [this] { exportWithDialog(Pdf); });
    m_export->setMenu(menu);

    m_plot = new MonitorPlot(this);
    m_plot->setMinimumHeight(200);
    m_readout = new QLabel(this);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_step = new StepControl(this);

    auto *controls = new QHBoxLayout;
    controls->addWidget(m_run);
    controls->addWidget(m_rateLabel);
    controls->addWidget(m_rate);
    controls->addWidget(m_achieved);
    controls->addSpacing(12);
    controls->addWidget(m_windowLabel);
    controls->addWidget(m_window);
    controls->addWidget(m_follow);
    controls->addStretch(1);
    controls->addWidget(m_channels);
    controls->addWidget(m_clear);
    controls->addWidget(m_export);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_readout);
    layout->addWidget(m_step);

    m_redraw.setSingleShot(true);
    m_redraw.setInterval(kMinRedrawMs);
    connect(&m_redraw, &QTimer::timeout, this, &MonitorView::redraw);
    connect(m_session, &model::MonitorSession::sampled, this, &MonitorView::scheduleRedraw);
    connect(m_session, &model::MonitorSession::journalChanged, this, &MonitorView::scheduleRedraw);
    connect(m_session, &model::MonitorSession::channelsChanged, this,
            &MonitorView::rebuildPlotChannels);
    connect(m_session, &model::MonitorSession::runningChanged, this, [this] {
        updateControls();
        updateRateLabel();
    });
    connect(m_session, &model::MonitorSession::pollFailed, this,
            [this](int module, const QString &reason) {
                // A lost link fails every poll: say it once, then again only when it changes or
                // after a while.
                const QString text = tr("Monitor, module %1: %2").arg(module).arg(reason);
                if (text == m_lastFailure && m_sinceFailure.isValid() &&
                    m_sinceFailure.elapsed() < kFailureRepeatMs)
                    return;
                m_lastFailure = text;
                m_sinceFailure.start();
                emit statusMessage(text);
            });
    connect(m_run, &QPushButton::toggled, this, [this](bool on) { on ? start() : pause(); });
    connect(m_run, &QPushButton::clicked, this, [this](bool on) {
        if (!on)
            emit stoppedByUser();
    });
    connect(m_rate, &QDoubleSpinBox::valueChanged, this,
            [this](double hz) { m_session->setRate(hz); });
    connect(m_window, &QDoubleSpinBox::valueChanged, this, [this] {
        setFollowing(true);
        scheduleRedraw();
    });
    for (NumberBox *box : {m_rate, m_window})
        connect(box, &NumberBox::refused, this, &MonitorView::statusMessage);
    connect(m_follow, &QCheckBox::toggled, this, &MonitorView::scheduleRedraw);
    connect(m_channels, &QPushButton::clicked, this, &MonitorView::chooseChannels);
    connect(m_clear, &QPushButton::clicked, this, [this] { m_session->clearRecording(); });
    connect(m_plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
            &MonitorView::onRangeChanged);
    connect(m_plot, &MonitorPlot::hovered, this, &MonitorView::showReadout);
    connect(m_step, &StepControl::written, this, &MonitorView::journalWrites);

    m_session->setRate(kDefaultRateHz);
    m_session->setLanguage(model::textLanguage());
    retranslate();
    updateControls();
}

MonitorView::~MonitorView()
{
    // The step's write job and the scheduler talk to the connection: both go before it.
    m_step->clearConnection();
    m_session->clearConnection();
}

void MonitorView::setConnection(model::Connection *c, std::vector<model::ModuleInfo> modules)
{
    m_step->clearConnection();
    m_session->setLanguage(model::textLanguage());
    m_session->setRate(m_rate->value());
    m_session->setConnection(c, modules);
    m_step->setConnection(c ? &c->access() : nullptr, modules);
    m_plot->setModules(modules);
    setFollowing(true);
    updateControls();
    updateRateLabel();
    scheduleRedraw();
}

void MonitorView::clearConnection()
{
    m_step->clearConnection();
    m_session->clearConnection();
    updateControls();
    updateRateLabel();
}

void MonitorView::journalWrites(int module, const std::vector<model::WriteItem> &items)
{
    m_session->journalWrites(module, items);
}

void MonitorView::start()
{
    m_session->start();
    setFollowing(true);
}

void MonitorView::pause()
{
    m_session->stop();
}

void MonitorView::setRate(double hz)
{
    m_rate->setValue(std::isfinite(hz) && hz > 0 ? hz : 0);
    m_session->setRate(m_rate->value());
}

void MonitorView::setWindowSeconds(double seconds)
{
    m_window->setValue(seconds);
}

double MonitorView::windowSeconds() const
{
    return m_window->value();
}

void MonitorView::setFollowing(bool on)
{
    m_follow->setChecked(on);
}

bool MonitorView::isFollowing() const
{
    return m_follow->isChecked();
}

int MonitorView::replotCount() const
{
    return m_plot->replotCount();
}

void MonitorView::scheduleRedraw()
{
    if (!isVisible()) {
        m_dirty = true; // drawn when shown (showEvent)
        return;
    }
    // Single shot, restarted only once it fired: at most one redraw per kMinRedrawMs however
    // fast samples arrive.
    if (!m_redraw.isActive())
        m_redraw.start();
}

void MonitorView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty) {
        m_dirty = false;
        scheduleRedraw();
    }
}

void MonitorView::redraw()
{
    if (!isVisible()) {
        m_dirty = true;
        return;
    }
    double t0 = m_plot->xAxis->range().lower;
    double t1 = m_plot->xAxis->range().upper;
    const bool follow = isFollowing();
    if (follow) {
        const double last = m_session->lastTime();
        t1 = std::isnan(last) ? m_session->now() : last;
        t0 = t1 - m_window->value();
    }
    m_applyingRange = true;
    m_plot->refresh(t0, t1, m_session->journal().markersIn(t0, t1), follow);
    m_applyingRange = false;
    if (const auto cursor = m_plot->cursorTime())
        m_readout->setText(m_plot->readout(*cursor).join(QStringLiteral("   ")));
    updateRateLabel();
}

void MonitorView::onRangeChanged()
{
    if (m_applyingRange)
        return;
    // The user dragged or zoomed the time axis: stop following and load the new range.
    setFollowing(false);
    scheduleRedraw();
}

void MonitorView::showReadout(double t)
{
    m_plot->setCursorAt(t);
    m_readout->setText(m_plot->readout(t).join(QStringLiteral("   ")));
}

QString MonitorView::readoutText() const
{
    return m_readout->text();
}

void MonitorView::rebuildPlotChannels()
{
    const std::vector<int> modules = m_session->monitoredModules();
    const bool prefix = modules.size() > 1;
    const dev::Language lang = model::textLanguage();
    std::vector<PlotChannel> channels;
    for (int module : modules) {
        const model::SampleStore *store = m_session->store(module);
        const auto rows = m_session->channels(module);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const QString name = QString::fromStdString(rows[i]->name);
            channels.push_back(
                PlotChannel{store, static_cast<int>(i),
                            prefix ? QStringLiteral("%1/%2").arg(module).arg(name) : name,
                            QString::fromStdString(rows[i]->label.in(lang)),
                            QString::fromStdString(rows[i]->unit), rows[i]->scale.decimals});
        }
    }
    m_plot->setChannels(std::move(channels));
    m_readout->clear();
    m_plot->setCursorAt(std::nullopt);
    updateControls();
    scheduleRedraw();
}

void MonitorView::chooseChannels()
{
    std::map<int, std::vector<const dev::ParamMeta *>> offered, selected;
    for (const model::ModuleInfo &module : m_session->modules())
        offered[module.address] = model::monitorableRows(module);
    for (int module : m_session->monitoredModules())
        selected[module] = m_session->channels(module);
    ChannelChooser chooser(m_session->modules(), offered, selected, model::textLanguage(), this);
    if (chooser.exec() == QDialog::Accepted)
        setChannels(chooser.selection());
}

void MonitorView::setChannels(const std::map<int, std::vector<const dev::ParamMeta *>> &selection)
{
    for (int module : m_session->monitoredModules()) {
        if (!selection.count(module))
            m_session->setChannels(module, {});
    }
    for (const auto &[module, rows] : selection) {
        // Unchanged modules keep their recording.
        if (m_session->channels(module) != rows)
            m_session->setChannels(module, rows);
    }
}

void MonitorView::updateRateLabel()
{
    m_achieved->setText(achievedRateText());
}

QString MonitorView::achievedRateText() const
{
    const std::vector<int> modules = m_session->monitoredModules();
    if (!m_session->isRunning() || modules.empty())
        return tr("achieved: –");
    const QLocale locale;
    QStringList parts;
    for (int module : modules) {
        const QString hz = locale.toString(m_session->achievedRate(module), 'f', 1);
        parts.append(modules.size() > 1 ? tr("%1: %2 Hz").arg(module).arg(hz)
                                        : tr("%1 Hz").arg(hz));
    }
    return tr("achieved: %1").arg(parts.join(QStringLiteral(", ")));
}

void MonitorView::updateControls()
{
    const bool connected = m_session->connection() != nullptr;
    const bool hasChannels = !m_session->monitoredModules().empty();
    {
        const QSignalBlocker block(m_run);
        m_run->setChecked(m_session->isRunning());
    }
    m_run->setText(m_session->isRunning() ? tr("Pause") : tr("Start"));
    m_run->setEnabled(connected && hasChannels);
    // Start is never disabled without a word: say why there is nothing to poll.
    const QString why =
        connected && !hasChannels
            ? tr("Nothing to monitor: the parameter list of this module names no default "
                 "channels. Choose the values to plot with Channels….")
            : QString();
    m_run->setToolTip(why);
    if (!why.isEmpty())
        m_readout->setText(why);
    m_channels->setEnabled(connected);
    m_export->setEnabled(hasChannels);
}

bool MonitorView::exportCsv(const QString &path, bool visibleOnly, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        if (error)
            *error = file.errorString();
        return false;
    }
    const double inf = std::numeric_limits<double>::infinity();
    const double t0 = visibleOnly ? m_plot->xAxis->range().lower : -inf;
    const double t1 = visibleOnly ? m_plot->xAxis->range().upper : inf;
    if (!model::writeMonitorCsv(*m_session, file, t0, t1, error))
        return false;
    if (!file.flush()) {
        if (error)
            *error = file.errorString();
        return false;
    }
    return true;
}

bool MonitorView::exportPng(const QString &path)
{
    return m_plot->exportPng(path);
}

bool MonitorView::exportPdf(const QString &path)
{
    return m_plot->exportPdf(path);
}

void MonitorView::exportWithDialog(int kind)
{
    const bool csv = kind == CsvVisible || kind == CsvAll;
    const QString filter = csv           ? tr("CSV files (*.csv)")
                           : kind == Png ? tr("PNG images (*.png)")
                                         : tr("PDF files (*.pdf)");
    const QString suffix = csv           ? QStringLiteral(".csv")
                           : kind == Png ? QStringLiteral(".png")
                                         : QStringLiteral(".pdf");
    QString path = QFileDialog::getSaveFileName(this, tr("Export monitor"), QString(), filter);
    if (path.isEmpty())
        return;
    if (!path.endsWith(suffix, Qt::CaseInsensitive))
        path += suffix;
    QString error;
    bool ok = false;
    if (csv)
        ok = exportCsv(path, kind == CsvVisible, &error);
    else
        ok = kind == Png ? exportPng(path) : exportPdf(path);
    emit statusMessage(ok ? tr("Exported to %1").arg(QDir::toNativeSeparators(path))
                          : tr("Export to %1 failed: %2")
                                .arg(QDir::toNativeSeparators(path),
                                     error.isEmpty() ? tr("could not write the file") : error));
}

void MonitorView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        m_session->setLanguage(model::textLanguage());
        rebuildPlotChannels(); // legend names come from the dictionary in the new language
    }
    QWidget::changeEvent(event);
}

void MonitorView::retranslate()
{
    m_rateLabel->setText(tr("Rate:"));
    m_rate->setSuffix(tr(" Hz"));
    m_rate->setSpecialValueText(tr("as fast as the link allows"));
    m_rate->setToolTip(tr("Polls per second and module; the lowest value polls back to back, as "
                          "fast as the link allows."));
    m_windowLabel->setText(tr("Window:"));
    m_window->setSuffix(tr(" s"));
    m_follow->setText(tr("Follow"));
    m_follow->setToolTip(
        tr("Keep the newest samples in view. Dragging or zooming the time axis turns this off."));
    m_channels->setText(tr("Channels…"));
    m_clear->setText(tr("Clear"));
    m_export->setText(tr("Export"));
    m_exportVisible->setText(tr("Visible range as CSV…"));
    m_exportAll->setText(tr("Everything as CSV…"));
    m_exportPng->setText(tr("Plot as PNG…"));
    m_exportPdf->setText(tr("Plot as PDF…"));
    m_plot->retranslate();
    updateControls();
    updateRateLabel();
}

} // namespace vt::ui
