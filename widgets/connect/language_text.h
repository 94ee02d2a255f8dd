// The dictionary texts the connect and new-file dialogs share, in the UI language
// (model/text_language.h).
#pragma once

#include "core/local_text.h"

#include <QString>
#include <string>

namespace vt::dev {
struct Dictionary;
}

namespace vt::ui {

// "Title (family-id)" for family lists.
QString familyText(const dev::Dictionary &dictionary);
// An HCS mode with its E00 label, "3 — Closed loop one valve"; other modes as listed ("vpoc").
QString modeText(const dev::Dictionary &dictionary, const std::string &mode);

} // namespace vt::ui
