// LinkStatusWidget: the status bar's view of the connection — what the link is and its state,
// which modules answered (identity, version, mode) and the session's request, retry, timeout and
// error counters, refreshed live (coalesced to at most 10 updates a second).
// Does not own the connection; forgets it when it is destroyed. GUI thread.
#pragma once

#include "model/session/device_access.h"

#include <QPointer>
#include <QString>
#include <QTimer>
#include <QWidget>
#include <vector>

class QLabel;

namespace vt::model {
class Connection;
}

namespace vt::ui {

class LinkStatusWidget : public QWidget
{
    Q_OBJECT
public:
    explicit LinkStatusWidget(QWidget *parent = nullptr);

    // Follows `connection` (its link state, failures and session counters); `modules` are the
    // identified modules, empty before identification (setModules() adds them later).
    void setConnection(model::Connection *connection,
                       const std::vector<model::ModuleInfo> &modules);
    void setModules(const std::vector<model::ModuleInfo> &modules);
    // Back to "not connected".
    void clearConnection();

    // The texts shown, for tests and tool tips.
    QString linkText() const;
    QString identityText() const;
    QString countersText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();
    void scheduleRefresh();
    QString moduleText(const model::ModuleInfo &module) const;

    QPointer<model::Connection> m_connection;
    std::vector<model::ModuleInfo> m_modules;
    QString m_reason; // why the link failed or was lost, until it opens again
    QLabel *m_link = nullptr;
    QLabel *m_identity = nullptr;
    QLabel *m_counters = nullptr;
    QTimer m_refresh;
};

} // namespace vt::ui
