#include "device_state_control.h"

#include "app/gui/workspace.h"
#include "dict/cooking.h"
#include "dsp408/pzd.h"
#include "model/session/write_job.h"
#include "model/text_language.h"
#include "widgets/actuator_confirm.h"

#include <QWidget>

namespace vt::app {

namespace {

// The rows the node view may write: the state machine's control word and the two mode rows.
const dev::ParamMeta *stateRow(const model::ParamModule &module, const std::string &name)
{
    const dev::ParamMeta *control =
        module.dictionary ? module.dictionary->stateControlWord() : nullptr;
    if (!control)
        return nullptr;
    if (name == control->name)
        return control;
    if (name != "db_Local" && name != "db_DeviceMode")
        return nullptr;
    const dev::ParamMeta *row = module.dictionary->find(name);
    return row && row->writable() ? row : nullptr;
}

const dev::ParamMeta *controlWordRow(const model::ParamModule &module)
{
    return module.dictionary ? module.dictionary->stateControlWord() : nullptr;
}

} // namespace

DeviceStateControl::DeviceStateControl(Workspace &workspace, QWidget *window)
    : QObject(window), m_workspace(workspace), m_window(window)
{
}

DeviceStateControl::~DeviceStateControl() = default;

void DeviceStateControl::resetFault(int moduleIndex)
{
    if (moduleIndex < 0 || moduleIndex >= m_workspace.document().moduleCount())
        return;
    const model::ParamModule &module = m_workspace.document().module(moduleIndex);
    const dev::ParamMeta *row = controlWordRow(module);
    if (!row)
        return;
    const auto last = m_workspace.deviceImage().value(module.address, row);
    const std::uint32_t keep = 0xFFFFu ^ dev::dsp408::control::kResetFault;
    const auto word =
        static_cast<quint16>(last ? static_cast<std::uint32_t>(dev::rawNumber(*last)) & keep : 0u);
    request(moduleIndex, static_cast<quint16>(word | dev::dsp408::control::kResetFault));
}

void DeviceStateControl::request(int moduleIndex, quint16 controlWord)
{
    requestValue(moduleIndex, QStringLiteral("db_ControlWord"), double(controlWord));
}

void DeviceStateControl::requestValue(int moduleIndex, const QString &rowName, double value)
{
    if (!m_workspace.isConnected() || moduleIndex < 0 ||
        moduleIndex >= m_workspace.document().moduleCount())
        return;
    const model::ParamModule &module = m_workspace.document().module(moduleIndex);
    const dev::ParamMeta *row = stateRow(module, rowName.toStdString());
    if (!row || !module.online) {
        emit statusMessage(tr("Module %1 has no writable %2.").arg(module.address).arg(rowName));
        return;
    }
    if (m_job && m_job->isRunning()) {
        emit statusMessage(tr("A device state write is still running."));
        return;
    }
    const QString line = ui::actuatorWriteLine(module.address, *row,
                                               m_workspace.deviceImage().value(module.address, row),
                                               dev::RawValue{value}, model::textLanguage());
    ui::confirmActuatorWrites(
        m_window, {line},
        [this, guard = QPointer<DeviceStateControl>(this), moduleIndex, row, value] {
            if (guard)
                write(moduleIndex, *row, value);
        });
}

void DeviceStateControl::write(int moduleIndex, const dev::ParamMeta &rowRef, double value)
{
    model::Connection *connection = m_workspace.connection();
    if (!m_workspace.isConnected() || !connection ||
        moduleIndex >= m_workspace.document().moduleCount())
        return;
    const model::ParamModule &module = m_workspace.document().module(moduleIndex);
    // The document may have been rebuilt while the question was open: the row must still be
    // this module's.
    const dev::ParamMeta *row = stateRow(module, rowRef.name);
    if (row != &rowRef)
        return;
    model::WriteItem item;
    item.row = row;
    item.value = dev::RawValue{value};
    item.before = m_workspace.deviceImage().value(module.address, row);
    const int address = module.address;
    m_job = std::make_unique<model::WriteJob>(connection->access(), address, *module.dictionary,
                                              std::vector<model::WriteItem>{item},
                                              model::AuditOrigin::State);
    connect(m_job.get(), &model::WriteJob::finished, this, [this, address](bool complete) {
        const std::vector<model::WriteItem> items = m_job->items();
        const model::WriteItem &done = items.front();
        const QString name = QString::fromStdString(done.row->name);
        const QString text =
            done.row->name == "db_ControlWord"
                ? QStringLiteral("0x%1").arg(static_cast<int>(dev::rawNumber(done.value)), 4, 16,
                                             QLatin1Char('0'))
                : QString::fromStdString(dev::formatValue(*done.row, dev::rawNumber(done.value),
                                                          model::textLanguage()));
        emit statusMessage(complete
                               ? tr("%1 = %2 written to module %3 (%4).")
                                     .arg(name, text)
                                     .arg(address)
                                     .arg(model::writeStatusText(done.status))
                               : tr("%1 = %2 not written to module %3: %4")
                                     .arg(name, text)
                                     .arg(address)
                                     .arg(model::writeReasonText(done, model::textLanguage())));
        emit written(address, items);
    });
    m_job->start();
}

} // namespace vt::app
