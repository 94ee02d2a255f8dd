#include "set_value_step.h"

#include "dict/cooking.h"

#include <QPointer>

namespace vt::model {

std::vector<const dev::ParamMeta *> SetValueStep::setValueRows(const dev::Dictionary &dictionary)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const char *name : {"A1.01", "A2.01"}) {
        const dev::ParamMeta *row = dictionary.find(name);
        if (row && row->writable() && !row->isString())
            rows.push_back(row);
    }
    return rows;
}

const dev::ParamMeta *SetValueStep::activationRow(const dev::Dictionary &dictionary)
{
    const dev::ParamMeta *row = dictionary.find("E17");
    return row && row->readable() && row->writable() ? row : nullptr;
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

QString SetValueStep::refusalText(const dev::ParamMeta &setValueRow, const dev::ParamMeta &e17Row,
                                  double e17, dev::Language lang)
{
    return tr("E17 (set value activation mode) is %1: the analogue set value is added to the bus "
              "set value %2, so the controller would not see the step alone. The manuals: \"For "
              "switching off of the analogue set-value, set E17 = 2\" (DMA manual, ID 0x1F) and "
              "\"If only the set value by the PLC is used … E17 = 2 is required\" (OPAT manual "
              "§5.3). "
              "Set E17 to 2 (only the digital set values active) first.")
        .arg(QString::fromStdString(dev::formatValue(e17Row, e17, lang)),
             QString::fromStdString(setValueRow.name));
}

void SetValueStep::step(const dev::ParamMeta &row, double raw)
{
    if (m_busy)
        return;
    const dev::ParamMeta *e17 = m_module.dictionary ? activationRow(*m_module.dictionary) : nullptr;
    if (!e17) {
        emit refused(tr("This module has no set value activation mode E17; a bus set value step is "
                        "not offered for it."),
                     false);
        return;
    }
    m_busy = true;
    const dev::ParamMeta *target = &row;
    // The answer may come after this object is gone (the handle only cancels what is queued).
    QPointer<SetValueStep> self(this);
    m_read =
        m_access.read(m_module.address, {e17, target}, Priority::User,
                      [self, this, e17, target, raw](const ReadResult &result) {
                          if (!self)
                              return;
                          if (!result.complete() || result.values.size() != 2) {
                              m_busy = false;
                              const QString why = result.failures.empty()
                                                      ? tr("cancelled")
                                                      : result.failures.front().outcome.reason;
                              emit refused(tr("Reading E17 failed: %1").arg(why), false);
                              return;
                          }
                          m_activation = dev::rawNumber(result.values[0].value);
                          if (*m_activation != kBusSetValueOnly) {
                              m_busy = false;
                              emit refused(refusalText(*target, *e17, *m_activation, m_lang), true);
                              return;
                          }
                          WriteItem item;
                          item.row = target;
                          item.value = raw;
                          item.before = result.values[1].value;
                          runJob({item});
                      });
}

void SetValueStep::enableBusSetValue()
{
    const dev::ParamMeta *e17 = m_module.dictionary ? activationRow(*m_module.dictionary) : nullptr;
    if (m_busy || !e17)
        return;
    m_busy = true;
    WriteItem item;
    item.row = e17;
    item.value = static_cast<double>(kBusSetValueOnly);
    if (m_activation)
        item.before = *m_activation;
    runJob({item});
}

void SetValueStep::runJob(std::vector<WriteItem> items)
{
    m_job = std::make_unique<WriteJob>(m_access, m_module.address, *m_module.dictionary,
                                       std::move(items));
    connect(m_job.get(), &WriteJob::finished, this, [this](bool complete) {
        m_busy = false;
        const std::vector<WriteItem> done = m_job->items();
        for (const WriteItem &item : done) {
            if (item.row && item.row->name == "E17" && isOnDevice(item.status))
                m_activation = dev::rawNumber(item.value);
        }
        // The job is not deleted inside its own signal.
        m_job->setParent(this);
        m_job.release()->deleteLater();
        emit written(m_module.address, done, complete);
    });
    m_job->start();
}

} // namespace vt::model
