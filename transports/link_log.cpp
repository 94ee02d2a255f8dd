#include "link_log.h"

namespace vt::link {
Q_LOGGING_CATEGORY(lcLink, "vt.link")
} // namespace vt::link
