// The "vt.link" logging category shared by every link: programmer errors (send on a closed link,
// malformed CAN images) are logged here and recovered from (STYLE.md rule 12).
// Any thread may log.
#pragma once

#include <QLoggingCategory>

namespace vt::link {
Q_DECLARE_LOGGING_CATEGORY(lcLink)
} // namespace vt::link
