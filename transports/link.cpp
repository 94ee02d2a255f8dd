#include "link.h"

#include <QCoreApplication>

namespace vt::link {

void Link::setState(LinkState state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

QString linkStateText(LinkState state)
{
    switch (state) {
    case LinkState::Closed: return QCoreApplication::translate("vt::link::Link", "Not connected");
    case LinkState::Opening: return QCoreApplication::translate("vt::link::Link", "Connecting…");
    case LinkState::Open: return QCoreApplication::translate("vt::link::Link", "Connected");
    case LinkState::Failed:
        return QCoreApplication::translate("vt::link::Link", "Connection failed");
    }
    return {};
}

} // namespace vt::link
