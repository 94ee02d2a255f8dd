#include "set_value_step.h"

#include "dict/cooking.h"

#include <QPointer>
#include <QStringList>

namespace vt::model {

std::vector<const dev::ParamMeta *> SetValueStep::setValueRows(const dev::Dictionary &dictionary,
                                                               const std::string &mode)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const std::string &name : dictionary.monitor.forMode(mode).setValues) {
        const dev::ParamMeta *row = dictionary.find(name);
        if (row && row->writable() && !row->isString())
            rows.push_back(row);
    }
    return rows;
}

std::vector<const dev::SetValueActivation *>
SetValueStep::activationRules(const dev::Dictionary &dictionary, const std::string &mode)
{
    std::vector<const dev::SetValueActivation *> rules;
    for (const dev::SetValueActivation &rule : dictionary.monitor.forMode(mode).activation) {
        const dev::ParamMeta *row = ruleRow(dictionary, rule);
        const dev::ParamMeta *written = ruleWriteRow(dictionary, rule);
        if (row && row->readable() && written && written->writable())
            rules.push_back(&rule);
    }
    return rules;
}

const dev::ParamMeta *SetValueStep::ruleRow(const dev::Dictionary &dictionary,
                                            const dev::SetValueActivation &rule)
{
    return dictionary.find(rule.row);
}

const dev::ParamMeta *SetValueStep::ruleWriteRow(const dev::Dictionary &dictionary,
                                                 const dev::SetValueActivation &rule)
{
    return dictionary.find(rule.written());
}

dev::LocalText SetValueStep::noStepReason(const dev::Dictionary &dictionary,
                                          const std::string &mode)
{
    return dictionary.monitor.forMode(mode).noSetValue;
}

SetValueStep::SetValueStep(DeviceAccess &access, ModuleInfo module, QObject *parent)
    : QObject(parent), m_access(access), m_module(std::move(module))
{
}

SetValueStep::~SetValueStep()
{
    if (m_read)
        m_read->cancel();
    // WriteJob's exchanges call back into it: a running job stops after the exchange on the
    // wire and deletes itself then, instead of going away under its own callbacks.
    if (m_job && m_job->isRunning()) {
        WriteJob *job = m_job.release();
        job->setParent(nullptr);
        disconnect(job, nullptr, this, nullptr);
        connect(job, &WriteJob::finished, job, &QObject::deleteLater);
        job->cancel();
    }
}

QString SetValueStep::refusalText(const dev::ParamMeta &setValueRow,
                                  const dev::ParamMeta &activationRow,
                                  const dev::SetValueActivation &rule, double value,
                                  dev::Language lang)
{
    if (rule.state) {
        const auto now = dev::dsp408::stateOfStatusWord(
            static_cast<std::uint16_t>(static_cast<std::int64_t>(value)));
        const QString state = now ? QString::fromLatin1(dev::dsp408::stateName(*now))
                                  : QStringLiteral("0x%1").arg(static_cast<std::int64_t>(value), 4,
                                                               16, QLatin1Char('0'));
        return tr("The device is in state %1 (%2), so the bus set value %3 does not drive the "
                  "valve. The manual: %4 Switch it to %5 first (%6 = 0x%7).")
            .arg(state, QString::fromStdString(activationRow.name),
                 QString::fromStdString(setValueRow.name),
                 QString::fromStdString(rule.reason.in(lang)),
                 QString::fromLatin1(dev::dsp408::stateName(*rule.state)),
                 QString::fromStdString(rule.written()))
            .arg(static_cast<std::int64_t>(rule.value), 4, 16, QLatin1Char('0'));
    }
    const QString now = QString::fromStdString(dev::formatValue(activationRow, value, lang));
    const QString wanted =
        QString::fromStdString(dev::formatValue(activationRow, rule.value, lang));
    return tr("%1 is %2, so the bus set value %3 alone does not drive the valve. The manual: %4 "
              "Set %1 to %5 first.")
        .arg(QString::fromStdString(activationRow.name), now,
             QString::fromStdString(setValueRow.name), QString::fromStdString(rule.reason.in(lang)),
             wanted);
}

void SetValueStep::step(const dev::ParamMeta &row, double raw)
{
    if (m_busy || !m_module.dictionary)
        return;
    const auto rules = activationRules(*m_module.dictionary, m_module.identification.mode);
    m_busy = true;
    const dev::ParamMeta *target = &row;
    std::vector<const dev::ParamMeta *> rows;
    for (const dev::SetValueActivation *rule : rules)
        rows.push_back(ruleRow(*m_module.dictionary, *rule));
    rows.push_back(target);
    // The answer may come after this object is gone (the handle only cancels what is queued).
    QPointer<SetValueStep> self(this);
    m_read = m_access.read(
        m_module.address, rows, Priority::User,
        [self, this, rules, rows, target, raw](const ReadResult &result) {
            if (!self)
                return;
            if (!result.complete() || result.values.size() != rows.size()) {
                m_busy = false;
                const QString why = result.failures.empty()
                                        ? tr("cancelled")
                                        : result.failures.front().outcome.reason;
                QStringList names;
                for (const dev::ParamMeta *r : rows)
                    names << QString::fromStdString(r->name);
                emit refused(tr("Reading %1 failed: %2").arg(names.join(QStringLiteral(", ")), why),
                             false);
                return;
            }
            m_pending = nullptr;
            m_activation.reset();
            for (std::size_t i = 0; i < rules.size(); ++i) {
                const double held = dev::rawNumber(result.values[i].value);
                if (!rules[i]->holds(held)) {
                    m_busy = false;
                    m_pending = rules[i];
                    m_activation = held;
                    emit refused(refusalText(*target, *rows[i], *rules[i], held, m_lang), true);
                    return;
                }
            }
            WriteItem item;
            item.row = target;
            item.value = raw;
            item.before = result.values.back().value;
            runJob({item});
        });
}

void SetValueStep::enableBusSetValue()
{
    if (m_busy || !m_module.dictionary)
        return;
    if (!m_pending) { // before any refusal: the first rule (E17 = 2 on the HCS modules)
        const auto rules = activationRules(*m_module.dictionary, m_module.identification.mode);
        if (rules.empty())
            return;
        m_pending = rules.front();
    }
    const dev::ParamMeta *row = ruleWriteRow(*m_module.dictionary, *m_pending);
    if (!row)
        return;
    m_busy = true;
    WriteItem item;
    item.row = row;
    item.value = m_pending->value;
    if (m_activation && !m_pending->state) // a state rule read the status word, not this row
        item.before = *m_activation;
    runJob({item});
}

void SetValueStep::runJob(std::vector<WriteItem> items)
{
    m_job = std::make_unique<WriteJob>(m_access, m_module.address, *m_module.dictionary,
                                       std::move(items), AuditOrigin::Monitor);
    connect(m_job.get(), &WriteJob::finished, this, [this](bool complete) {
        m_busy = false;
        const std::vector<WriteItem> done = m_job->items();
        for (const WriteItem &item : done) {
            // The refused rule now holds its value: the next step checks the next rule.
            if (m_pending && item.row &&
                item.row == ruleWriteRow(*m_module.dictionary, *m_pending) &&
                isOnDevice(item.status)) {
                m_pending = nullptr;
                m_activation.reset();
            }
        }
        // The job is not deleted inside its own signal.
        m_job->setParent(this);
        m_job.release()->deleteLater();
        emit written(m_module.address, done, complete);
    });
    m_job->start();
}

} // namespace vt::model
