#include "actuator_ledger.h"

#include <algorithm>

namespace vt::model {

ActuatorLedger::ActuatorLedger(DeviceImage &image, QObject *parent)
    : QObject(parent), m_image(image)
{
    connect(&m_image, &DeviceImage::changed, this, &ActuatorLedger::onImageChanged);
}

ActuatorLedger::~ActuatorLedger() = default;

void ActuatorLedger::clear()
{
    if (m_changes.empty())
        return;
    m_changes.clear();
    emit changed();
}

void ActuatorLedger::onImageChanged(int module, const std::vector<ImageChange> &rows)
{
    bool any = false;
    for (const ImageChange &c : rows) {
        if (!c.row || !c.row->movesActuator)
            continue;
        const ImageEntry *entry = m_image.entry(module, c.row);
        auto it = std::find_if(m_changes.begin(), m_changes.end(), [&](const ActuatorChange &a) {
            return a.module == module && a.row == c.row;
        });
        if (!entry) {
            continue;
        } else if (entry->source == ImageSource::Written) {
            if (it == m_changes.end())
                m_changes.push_back({module, c.row, c.before, entry->value});
            else
                it->now = entry->value;
        } else if (it != m_changes.end()) {
            it->now = entry->value; // read back, or changed by the PLC since
        } else {
            continue;
        }
        any = true;
    }
    // A row back at its original value needs nothing put back.
    const auto settled =
        std::remove_if(m_changes.begin(), m_changes.end(),
                       [](const ActuatorChange &a) { return a.original && *a.original == a.now; });
    any = any || settled != m_changes.end();
    m_changes.erase(settled, m_changes.end());
    if (any)
        emit changed();
}

std::map<int, std::vector<WriteItem>> ActuatorLedger::restorePlan() const
{
    std::map<int, std::vector<WriteItem>> plan;
    // The set-value source last: set values go back while the bus still drives the valve, then
    // the source returns to the analogue input.
    std::vector<ActuatorChange> ordered = m_changes;
    std::stable_sort(
        ordered.begin(), ordered.end(), [](const ActuatorChange &a, const ActuatorChange &b) {
            return a.row->kind != dev::RowKind::Setting && b.row->kind == dev::RowKind::Setting;
        });
    for (const ActuatorChange &c : ordered) {
        if (!c.original)
            continue;
        WriteItem item;
        item.row = c.row;
        item.value = *c.original;
        item.before = c.now;
        plan[c.module].push_back(std::move(item));
    }
    return plan;
}

std::vector<ActuatorChange> ActuatorLedger::unrestorable() const
{
    std::vector<ActuatorChange> out;
    for (const ActuatorChange &c : m_changes)
        if (!c.original)
            out.push_back(c);
    return out;
}

} // namespace vt::model
