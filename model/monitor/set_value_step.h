// SetValueStep: the monitor's step test — writes a bus set value A1.01 / A2.01 so an
// engineer can watch the controller answer. The bus set value is always active once written,
// but the analogue set value is added to it unless E17 = 2 (DMA Profinet manual ID 0x1F: "For
// switching off of the analogue set-value, set E17 = 2"; OPAT manual §5.3: "If only the set value
// by the PLC is used … E17 = 2 is required"), so E17 is read first and the step refused while it
// is not 2. Every write goes through WriteJob (range check, pacing, read back).
// Owner: the monitor view; GUI thread, same as the DeviceAccess, which must outlive it.
#pragma once

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
    // E17 = 2: "only 4 digital active" (DMA Profinet manual / OPAT manual, ID 0x70).
    static constexpr int kBusSetValueOnly = 2;

    // The writable bus set values A1.01, A2.01 of a dictionary (empty for the Wandfluh families).
    static std::vector<const dev::ParamMeta *> setValueRows(const dev::Dictionary &dictionary);
    static const dev::ParamMeta *activationRow(const dev::Dictionary &dictionary); // E17

    SetValueStep(DeviceAccess &access, ModuleInfo module, QObject *parent = nullptr);
    ~SetValueStep() override;

    const ModuleInfo &module() const { return m_module; }
    bool isBusy() const { return m_busy; }

    // Reads E17 and `row`; writes `raw` to `row` only when E17 = 2, else refused() with the
    // manuals' explanation (and nothing is written).
    void step(const dev::ParamMeta &row, double raw);
    // Writes E17 = 2 (after the engineer agreed to switch the analogue set value off).
    void enableBusSetValue();

    // The last E17 value read (nullopt before the first read or when it failed).
    std::optional<double> activation() const { return m_activation; }
    // Language of the E17 value label in refused().
    void setLanguage(dev::Language lang) { m_lang = lang; }
    // Why E17 must be 2, for people; `e17` the value read.
    static QString refusalText(const dev::ParamMeta &setValueRow, const dev::ParamMeta &e17Row,
                               double e17, dev::Language lang);

signals:
    // The step was not written: E17 is not 2 (needsActivation) or reading failed.
    void refused(const QString &reason, bool needsActivation);
    // A write finished (the step, or E17): its items for the tuning journal.
    void written(int module, const std::vector<vt::model::WriteItem> &items, bool complete);

private:
    void runJob(std::vector<WriteItem> items);

    DeviceAccess &m_access;
    ModuleInfo m_module;
    std::unique_ptr<WriteJob> m_job;
    std::shared_ptr<DeviceAccess::ReadHandle> m_read;
    std::optional<double> m_activation;
    bool m_busy = false;
    dev::Language m_lang = dev::Language::English;
};

} // namespace vt::model
