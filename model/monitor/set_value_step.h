// SetValueStep: the monitor's step test — writes a bus set value (the dictionary's
// "monitor"."set_values": HCS A1.01 / A2.01, SD7 the command values) so an engineer can watch the
// controller answer. The set value drives the valve alone only while the activation row holds
// its value (HCS E17 = 2, DMA Profinet manual ID 0x1F: "For switching off of the analogue
// set-value, set E17 = 2"; SD7 db_DeviceMode = 1, HART-7 manual §5.2.3 "Command value from
// fieldbus"; ED1/SD1 and SD7 the device state DEVICE_MODE_ACTIVE, ED1/SD1 manual and HART-7
// manual §4.2.2), so that row is read first and the step refused while it differs. Every write goes
// through WriteJob (range check, pacing, read back).
// Owner: the monitor view; GUI thread, same as the DeviceAccess, which must outlive it.
#pragma once

#include "dict/monitor_defaults.h"
#include "model/session/device_access.h"
#include "model/session/write_job.h"

#include <QObject>
#include <memory>
#include <optional>

namespace vt::model {

class SetValueStep : public QObject
{
    Q_OBJECT
public:
    // The set values the step may write in `mode` (empty: no step, see noStepReason).
    static std::vector<const dev::ParamMeta *> setValueRows(const dev::Dictionary &dictionary,
                                                            const std::string &mode);
    // The rows that must hold their values before a set value drives the valve alone (E17 = 2;
    // SD7 db_Local = 0, db_DeviceMode = 1), in the order they are checked.
    static std::vector<const dev::SetValueActivation *>
    activationRules(const dev::Dictionary &dictionary, const std::string &mode);
    // The row a rule reads, and the row written to meet it (the same but for a state rule: the
    // status word is read, the control word written); null when the dictionary lacks it.
    static const dev::ParamMeta *ruleRow(const dev::Dictionary &dictionary,
                                         const dev::SetValueActivation &rule);
    static const dev::ParamMeta *ruleWriteRow(const dev::Dictionary &dictionary,
                                              const dev::SetValueActivation &rule);
    // Why `mode` of the family has no step (the dictionary's words).
    static dev::LocalText noStepReason(const dev::Dictionary &dictionary, const std::string &mode);

    SetValueStep(DeviceAccess &access, ModuleInfo module, QObject *parent = nullptr);
    ~SetValueStep() override;

    const ModuleInfo &module() const { return m_module; }
    bool isBusy() const { return m_busy; }

    // Reads the activation rows and `row`; writes `raw` to `row` only when each holds its value,
    // else refused() with the manuals' explanation of the first that differs (nothing written).
    void step(const dev::ParamMeta &row, double raw);
    // Writes the refused rule's value (E17 = 2) after the engineer agreed; before any refusal,
    // the first rule's.
    void enableBusSetValue();

    // The rule the last step was refused for and the value its row held (null / nullopt before a
    // refusal, or after the rule's value was written).
    const dev::SetValueActivation *pendingRule() const { return m_pending; }
    std::optional<double> activation() const { return m_activation; }
    // Language of the activation value label in refused().
    void setLanguage(dev::Language lang) { m_lang = lang; }
    // Why the activation row must hold its value, for people; `value` the value read.
    static QString refusalText(const dev::ParamMeta &setValueRow,
                               const dev::ParamMeta &activationRow,
                               const dev::SetValueActivation &rule, double value,
                               dev::Language lang);

signals:
    // The step was not written: the activation row differs (needsActivation) or reading failed.
    void refused(const QString &reason, bool needsActivation);
    // A write finished (the step, or E17): its items for the tuning journal.
    void written(int module, const std::vector<vt::model::WriteItem> &items, bool complete);

private:
    void runJob(std::vector<WriteItem> items);

    DeviceAccess &m_access;
    ModuleInfo m_module;
    std::unique_ptr<WriteJob> m_job;
    std::shared_ptr<DeviceAccess::ReadHandle> m_read;
    const dev::SetValueActivation *m_pending = nullptr;
    std::optional<double> m_activation;
    bool m_busy = false;
    dev::Language m_lang = dev::Language::English;
};

} // namespace vt::model
