// DeviceImage: what is known to be on each module of the connected node — per row the value the
// device last answered (a read, or a write it acknowledged), when, and on which connection.
// Nothing else keeps a copy: the editor's Device column, "differs from device", Compare, Write
// Changes and the monitor read it; DeviceAccess updates it from every answer. A value from before
// the current connection or older than maxAge() is not current: shown as such, read again before
// anything is written on its strength.
// Owner: the workspace (GUI) or whoever made the DeviceAccess; GUI thread.
#pragma once

#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <QObject>
#include <chrono>
#include <map>
#include <optional>
#include <vector>

namespace vt::model {

enum class ImageSource {
    Read,   // the device answered a read
    Written // the device acknowledged a write of this value (not yet read back)
};

struct ImageEntry
{
    dev::RawValue value;
    ImageSource source = ImageSource::Read;
    std::chrono::steady_clock::time_point when;
    quint64 connection = 0; // DeviceImage::connection() at the time
};

struct ImageChange
{
    const dev::ParamMeta *row = nullptr;
    std::optional<dev::RawValue> before; // the image's value before, current or not
};

class DeviceImage : public QObject
{
    Q_OBJECT
public:
    using Clock = std::chrono::steady_clock;

    explicit DeviceImage(QObject *parent = nullptr);
    ~DeviceImage() override;

    // A new connection begins: everything known so far is from before it (kept for display,
    // never current again). endConnection(): the link is gone; nothing is current.
    void beginConnection();
    void endConnection();
    bool connected() const { return m_connected; }
    quint64 connection() const { return m_connection; }

    // Values older than this are not current (default 10 minutes): a PLC or another tool may
    // have changed them since.
    void setMaxAge(std::chrono::seconds age) { m_maxAge = age; }
    std::chrono::seconds maxAge() const { return m_maxAge; }

    // What the device answered. Emits changed() for rows whose value changed (a fresh time
    // alone is recorded silently).
    void recordRead(int module,
                    const std::vector<std::pair<const dev::ParamMeta *, dev::RawValue>> &values);
    void recordWritten(int module, const dev::ParamMeta *row, const dev::RawValue &value);
    // The value on the device is no longer known (a frame the image cannot follow was sent).
    void forget(int module, const dev::ParamMeta *row);

    const ImageEntry *entry(int module, const dev::ParamMeta *row) const;
    // The last known value, current or not.
    std::optional<dev::RawValue> value(int module, const dev::ParamMeta *row) const;
    // The value, only when it is current (this connection, younger than maxAge()).
    std::optional<dev::RawValue> currentValue(int module, const dev::ParamMeta *row) const;
    bool isCurrent(const ImageEntry &entry, Clock::time_point now = Clock::now()) const;

signals:
    void changed(int module, const std::vector<vt::model::ImageChange> &rows);
    // A connection began or ended: every entry's currency changed.
    void currencyChanged();

private:
    using Rows = std::map<const dev::ParamMeta *, ImageEntry>;
    std::map<int, Rows> m_modules;
    quint64 m_connection = 0;
    bool m_connected = false;
    std::chrono::seconds m_maxAge{600};
};

} // namespace vt::model
