// ConnectionMemory: the last spec of each link kind, and the kind last used, kept in the
// QSettings the caller passes (group "connection") so the connect dialog reopens as it was left.
// Only what the user chose is kept (no fault injection, timing overrides or module lists).
// Owns nothing; the QSettings must outlive it. GUI thread (QSettings is not shared across threads).
#pragma once

#include "model/session/connection.h"

#include <optional>

class QSettings;

namespace vt::ui {

class ConnectionMemory
{
public:
    explicit ConnectionMemory(QSettings &settings) : m_settings(settings) {}

    // Stores `spec` as its kind's last spec and its kind as the last used.
    void save(const model::ConnectionSpec &spec);
    // The last spec saved for `kind`; nothing when none was.
    std::optional<model::ConnectionSpec> load(model::ConnectionKind kind) const;
    std::optional<model::ConnectionKind> lastKind() const;

private:
    QSettings &m_settings;
};

} // namespace vt::ui
