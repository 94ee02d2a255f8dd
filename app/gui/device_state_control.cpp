#include "device_state_control.h"

#include "app/gui/workspace.h"
#include "dsp408/pzd.h"
#include "model/session/write_job.h"
#include "model/text_language.h"
#include "widgets/actuator_confirm.h"

#include <QWidget>

namespace vt::app {

namespace {

const dev::ParamMeta *controlWordRow(const model::ParamModule &module)
{
    if (!module.dictionary || module.dictionary->protocol != dev::DeviceProtocol::Dsp408)
        return nullptr;
    const dev::ParamMeta *row = module.dictionary->find("db_ControlWord");
    return row && row->writable() ? row : nullptr;
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
    if (!m_workspace.isConnected() || moduleIndex < 0 ||
        moduleIndex >= m_workspace.document().moduleCount())
        return;
    const model::ParamModule &module = m_workspace.document().module(moduleIndex);
    const dev::ParamMeta *row = controlWordRow(module);
    if (!row || !module.online) {
        emit statusMessage(tr("Module %1 has no DSP-408 control word.").arg(module.address));
        return;
    }
    if (m_job && m_job->isRunning()) {
        emit statusMessage(tr("A control word is still being written."));
        return;
    }
    const QString line = ui::actuatorWriteLine(
        module.address, *row, m_workspace.deviceImage().value(module.address, row),
        dev::RawValue{double(controlWord)}, model::textLanguage());
    ui::confirmActuatorWrites(
        m_window, {line},
        [this, guard = QPointer<DeviceStateControl>(this), moduleIndex, controlWord] {
            if (guard)
                write(moduleIndex, controlWord);
        });
}

void DeviceStateControl::write(int moduleIndex, quint16 controlWord)
{
    model::Connection *connection = m_workspace.connection();
    if (!m_workspace.isConnected() || !connection ||
        moduleIndex >= m_workspace.document().moduleCount())
        return;
    const model::ParamModule &module = m_workspace.document().module(moduleIndex);
    const dev::ParamMeta *row = controlWordRow(module);
    if (!row)
        return;
    model::WriteItem item;
    item.row = row;
    item.value = dev::RawValue{double(controlWord)};
    item.before = m_workspace.deviceImage().value(module.address, row);
    const int address = module.address;
    m_job = std::make_unique<model::WriteJob>(connection->access(), address, *module.dictionary,
                                              std::vector<model::WriteItem>{item});
    connect(m_job.get(), &model::WriteJob::finished, this, [this, address](bool complete) {
        const std::vector<model::WriteItem> items = m_job->items();
        const QString word = QStringLiteral("0x%1").arg(
            static_cast<int>(dev::rawNumber(items.front().value)), 4, 16, QLatin1Char('0'));
        emit statusMessage(
            complete ? tr("Control word %1 written to module %2.").arg(word).arg(address)
                     : tr("Control word %1 not written to module %2: %3")
                           .arg(word)
                           .arg(address)
                           .arg(model::writeReasonText(items.front(), model::textLanguage())));
        emit written(address, items);
    });
    m_job->start();
}

} // namespace vt::app
