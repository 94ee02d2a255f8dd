#include "widgets/fold/fold_bench_page.h"

#include "hcs/status_bits.h"
#include "model/fold/plc_test_bench.h"
#include "model/session/connection.h"
#include "model/text_language.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/number_box.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vt::ui {

namespace {

enum Column {
    ColModule,
    ColControl,
    ColValue1,
    ColValue2,
    ColStatus,
    ColAnswer1,
    ColAnswer2,
    ColTadr,
    ColCount
};

QString valueText(std::int16_t raw, const dev::hcs::ValueMeaning &meaning)
{
    // "1000 == 1.000 V" / "1000 == 1.000 A" (profiles.h): raw is thousandths.
    const QString unit = meaning.unit == dev::hcs::ValueUnit::Milliampere ? QStringLiteral("A")
                                                                          : QStringLiteral("V");
    return QStringLiteral("%1 %2 (%3)")
        .arg(QLocale().toString(raw / 1000.0, 'f', 3), unit,
             QString::fromLatin1(meaning.parameter.data(),
                                 static_cast<int>(meaning.parameter.size())));
}

QString bitsText(std::uint8_t byte, const std::array<dev::hcs::BitMeaning, 8> &bits)
{
    QStringList names;
    for (const dev::hcs::BitMeaning &bit : bits)
        if (bit.used && (byte & bit.mask))
            names << QString::fromLatin1(bit.name.data(), static_cast<int>(bit.name.size()));
    return names.join(QLatin1Char(' '));
}

} // namespace

FoldBenchPage::FoldBenchPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    m_intro->setObjectName(QStringLiteral("intro"));
    layout->addWidget(m_intro);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("bench"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    auto *row = new QHBoxLayout;
    m_start = new QPushButton(this);
    m_start->setObjectName(QStringLiteral("startBench"));
    m_stop = new QPushButton(this);
    m_stop->setObjectName(QStringLiteral("stopBench"));
    m_intervalLabel = new QLabel(this);
    m_interval = new WholeNumberBox(this);
    m_interval->setRange(5, 5000);
    m_interval->setValue(50);
    m_interval->setSuffix(QStringLiteral(" ms"));
    row->addWidget(m_start);
    row->addWidget(m_stop);
    row->addWidget(m_intervalLabel);
    row->addWidget(m_interval);
    row->addStretch();
    layout->addLayout(row);
    m_counters = new QLabel(this);
    m_counters->setObjectName(QStringLiteral("counters"));
    m_counters->setWordWrap(true);
    layout->addWidget(m_counters);
    connect(m_start, &QPushButton::clicked, this, &FoldBenchPage::startBench);
    connect(m_stop, &QPushButton::clicked, this, &FoldBenchPage::stopBench);
    connect(m_interval, &QSpinBox::valueChanged, this, [this](int ms) {
        if (m_bench)
            m_bench->setIntervalMs(ms);
    });
    retranslate();
}

FoldBenchPage::~FoldBenchPage()
{
    delete m_bench; // before the session it uses goes (the page goes with the wizard)
}

void FoldBenchPage::initializePage()
{
    buildTable();
    updateState();
}

void FoldBenchPage::cleanupPage()
{
    stopBench();
}

void FoldBenchPage::buildTable()
{
    const model::FoldPlan &plan = fold()->plan();
    const std::size_t count = std::min(plan.modules.size(), model::foldMaxCmd15Modules(plan.node));
    m_table->setRowCount(static_cast<int>(count));
    const dev::hcs::Family family = model::foldFamily(plan.node);
    for (int row = 0; row < m_table->rowCount(); ++row) {
        auto *item = new QTableWidgetItem(
            tr("Module %1 (SADR %2)")
                .arg(row + 1)
                .arg(dev::hcs::moduleAddress(family, static_cast<std::size_t>(row))));
        item->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, ColModule, item);
        auto *control = new QSpinBox(m_table);
        control->setRange(0, 255);
        control->setDisplayIntegerBase(16);
        control->setPrefix(QStringLiteral("0x"));
        m_table->setCellWidget(row, ColControl, control);
        for (int c : {ColValue1, ColValue2}) {
            auto *value = new WholeNumberBox(m_table);
            value->setRange(-32768, 32767);
            m_table->setCellWidget(row, c, value);
            connect(value, &QSpinBox::valueChanged, this, &FoldBenchPage::pushSetpoints);
        }
        connect(control, &QSpinBox::valueChanged, this, &FoldBenchPage::pushSetpoints);
        for (int c = ColStatus; c < ColCount; ++c) {
            auto *cell = new QTableWidgetItem;
            cell->setFlags(Qt::ItemIsEnabled);
            m_table->setItem(row, c, cell);
        }
    }
    m_table->resizeColumnsToContents();
}

bool FoldBenchPage::startBench()
{
    FoldWizard *wizard = fold();
    if (!wizard)
        return false;
    const model::FoldPlan &plan = wizard->plan();
    model::Connection *connection = wizard->connection();
    if (!wizard->online() || !model::PlcTestBench::supports(connection->session())) {
        m_counters->setText(unavailableText());
        return false;
    }
    const dev::hcs::Family family = model::foldFamily(plan.node);
    const QString why = model::PlcTestBench::checkModules(family, plan.modules.size());
    if (!why.isEmpty()) {
        m_counters->setText(why);
        return false;
    }
    if (!m_bench) {
        m_bench = new model::PlcTestBench(connection->session(), family, plan.modules.size(), this);
        for (std::size_t i = 0; i < plan.modules.size(); ++i)
            m_bench->setProfile(i, model::foldProfile(plan.node, plan.modules[i]));
        connect(m_bench, &model::PlcTestBench::moduleAnswered, this, &FoldBenchPage::showAnswer);
        connect(m_bench, &model::PlcTestBench::countersChanged, this, &FoldBenchPage::showCounters);
        connect(m_bench, &model::PlcTestBench::stopped, this, [this](const QString &reason) {
            updateState();
            m_counters->setText(reason);
        });
    }
    m_bench->setIntervalMs(m_interval->value());
    pushSetpoints();
    m_bench->start();
    updateState();
    return true;
}

void FoldBenchPage::dropBench()
{
    delete m_bench;
    updateState();
}

void FoldBenchPage::stopBench()
{
    if (m_bench)
        m_bench->stop();
    updateState();
}

void FoldBenchPage::pushSetpoints()
{
    if (!m_bench)
        return;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto spin = [this, row](int c) {
            return qobject_cast<QSpinBox *>(m_table->cellWidget(row, c));
        };
        if (!spin(ColControl) || !spin(ColValue1) || !spin(ColValue2))
            continue;
        dev::hcs::ModuleSetpoints sp;
        sp.control = static_cast<std::uint8_t>(spin(ColControl)->value());
        sp.value1 = static_cast<std::int16_t>(spin(ColValue1)->value());
        sp.value2 = static_cast<std::int16_t>(spin(ColValue2)->value());
        m_bench->setSetpoints(static_cast<std::size_t>(row), sp);
    }
}

void FoldBenchPage::showAnswer(int index)
{
    if (!m_bench || index < 0 || index >= m_table->rowCount())
        return;
    const model::BenchModule &module = m_bench->modules()[static_cast<std::size_t>(index)];
    if (!module.last)
        return;
    const dev::hcs::CyclicResponse &answer = *module.last;
    const dev::hcs::Profile profile =
        module.profile.value_or(dev::hcs::defaultProfile(m_bench->family()));
    const dev::hcs::ProfileInfo &info = dev::hcs::profileInfo(profile);
    const dev::hcs::ModuleStatus status = dev::hcs::decodeStatus(answer.status);
    QString statusText = QStringLiteral("0x%1 %2")
                             .arg(answer.status, 4, 16, QLatin1Char('0'))
                             .arg(bitsText(static_cast<std::uint8_t>(answer.status >> 8),
                                           dev::hcs::statusHighBits(profile)));
    if (status.error) {
        const auto text = dev::hcs::errorNumberText(m_bench->family(), status.errorNumber);
        statusText += QStringLiteral(" — ") +
                      (text ? model::localText(*text) : tr("error %1").arg(status.errorNumber));
    } else {
        const QString low = bitsText(static_cast<std::uint8_t>(answer.status & 0xFF),
                                     dev::hcs::statusLowBits(profile));
        if (!low.isEmpty())
            statusText += QLatin1Char(' ') + low;
    }
    m_table->item(index, ColStatus)->setText(statusText);
    m_table->item(index, ColAnswer1)->setText(valueText(answer.value1, info.response1));
    m_table->item(index, ColAnswer2)->setText(valueText(answer.value2, info.response2));
    QStringList tadrs;
    for (std::uint8_t t : module.tadrs)
        tadrs << QString::number(t);
    m_table->item(index, ColTadr)
        ->setText(tr("%1 (%n answer(s))", "", static_cast<int>(module.answers))
                      .arg(tadrs.mid(std::max<qsizetype>(0, tadrs.size() - 4))
                               .join(QStringLiteral(", "))));
}

void FoldBenchPage::showCounters()
{
    if (!m_bench)
        return;
    const model::BenchCounters &c = m_bench->counters();
    m_counters->setText(
        tr("Telegrams sent %1, answers %2, stale %3, exceptions %4, no answer %5; TADR %6")
            .arg(c.sent)
            .arg(c.answered)
            .arg(c.stale)
            .arg(c.exceptions)
            .arg(c.failures)
            .arg(m_bench->lastTadr()));
}

QString FoldBenchPage::unavailableText() const
{
    // Why, and what to connect: the bench talks to the node as a PLC does, through its image.
    const QString what =
        tr("Connect the node's fieldbus gateway over TCP with the protocol \"node-image\" "
           "(Device ▸ Connect…), or the simulator with the protocol \"node-image\".");
    FoldWizard *wizard = fold();
    if (!wizard || !wizard->online())
        return tr("Not available: no node is connected.") + QLatin1Char(' ') + what;
    return tr("Not available: the connection speaks %1, and the test bench needs the node's "
              "cyclic CMD 15 image.")
               .arg(QString::fromLatin1(dev::key(wizard->connection()->protocol()))) +
           QLatin1Char(' ') + what;
}

void FoldBenchPage::updateState()
{
    FoldWizard *wizard = fold();
    if (!wizard)
        return;
    const bool usable =
        wizard->online() && model::PlcTestBench::supports(wizard->connection()->session());
    const bool running = m_bench && m_bench->isRunning();
    m_start->setEnabled(usable && !running);
    m_stop->setEnabled(running);
    m_intro->setText(usable ? tr("Sends CMD 15 to every module with the values below, TADR "
                                 "changing every telegram, and shows each module's answer as the "
                                 "node multiplexes them (DMA Profinet manual §4.2, OPAT manual "
                                 "§3.2).")
                            : unavailableText());
}

void FoldBenchPage::retranslate()
{
    setTitle(tr("PLC test bench"));
    setSubTitle(
        tr("The check a PLC programmer does: cyclic CMD 15 telegrams and the decoded answers."));
    m_table->setHorizontalHeaderLabels({tr("Module"), tr("Control byte"), tr("VALUE1 out"),
                                        tr("VALUE2 out"), tr("Status word"), tr("VALUE1 in"),
                                        tr("VALUE2 in"), tr("Recent TADR")});
    m_start->setText(tr("Start"));
    m_stop->setText(tr("Stop"));
    m_intervalLabel->setText(tr("Cycle:"));
    if (fold())
        updateState();
}

} // namespace vt::ui
