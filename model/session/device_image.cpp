#include "device_image.h"

#include "core/vt_assert.h"

namespace vt::model {

DeviceImage::DeviceImage(QObject *parent) : QObject(parent)
{
}

DeviceImage::~DeviceImage() = default;

void DeviceImage::beginConnection()
{
    ++m_connection;
    m_connected = true;
    emit currencyChanged();
}

void DeviceImage::endConnection()
{
    if (!m_connected)
        return;
    m_connected = false;
    emit currencyChanged();
}

void DeviceImage::recordRead(
    int module, const std::vector<std::pair<const dev::ParamMeta *, dev::RawValue>> &values)
{
    const auto now = Clock::now();
    Rows &rows = m_modules[module];
    std::vector<ImageChange> changes;
    for (const auto &[row, value] : values) {
        if (!row)
            continue;
        auto it = rows.find(row);
        if (it == rows.end()) {
            rows.emplace(row, ImageEntry{value, ImageSource::Read, now, m_connection});
            changes.push_back({row, std::nullopt});
            continue;
        }
        const bool wasCurrent = isCurrent(it->second, now);
        const bool same = it->second.value == value;
        if (!same || !wasCurrent)
            changes.push_back({row, it->second.value});
        it->second = ImageEntry{value, ImageSource::Read, now, m_connection};
    }
    if (!changes.empty())
        emit changed(module, changes);
}

void DeviceImage::recordWritten(int module, const dev::ParamMeta *row, const dev::RawValue &value)
{
    VT_ASSERT(row, return ); // DeviceAccess::write() passes the row it wrote
    Rows &rows = m_modules[module];
    std::optional<dev::RawValue> before;
    if (auto it = rows.find(row); it != rows.end())
        before = it->second.value;
    rows[row] = ImageEntry{value, ImageSource::Written, Clock::now(), m_connection};
    emit changed(module, {ImageChange{row, before}});
}

void DeviceImage::forget(int module, const dev::ParamMeta *row)
{
    auto m = m_modules.find(module);
    if (m == m_modules.end())
        return;
    auto it = m->second.find(row);
    if (it == m->second.end())
        return;
    ImageChange change{row, it->second.value};
    m->second.erase(it);
    emit changed(module, {change});
}

const ImageEntry *DeviceImage::entry(int module, const dev::ParamMeta *row) const
{
    auto m = m_modules.find(module);
    if (m == m_modules.end())
        return nullptr;
    auto it = m->second.find(row);
    return it == m->second.end() ? nullptr : &it->second;
}

std::optional<dev::RawValue> DeviceImage::value(int module, const dev::ParamMeta *row) const
{
    const ImageEntry *e = entry(module, row);
    return e ? std::optional<dev::RawValue>(e->value) : std::nullopt;
}

std::optional<dev::RawValue> DeviceImage::currentValue(int module, const dev::ParamMeta *row) const
{
    const ImageEntry *e = entry(module, row);
    return e && isCurrent(*e) ? std::optional<dev::RawValue>(e->value) : std::nullopt;
}

bool DeviceImage::isCurrent(const ImageEntry &entry, Clock::time_point now) const
{
    return m_connected && entry.connection == m_connection && now - entry.when <= m_maxAge;
}

} // namespace vt::model
