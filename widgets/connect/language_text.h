// The product language as the widgets see it (the default QLocale, which app/gui/language.cpp
// sets on every switch), for picking one side of the core's {en, de} texts, and the dictionary
// texts the connect and new-file dialogs share.
#pragma once

#include "core/local_text.h"

#include <QString>
#include <string>

namespace vt::dev {
struct Dictionary;
}

namespace vt::ui {

dev::Language uiLanguage();
QString localText(const dev::LocalText &text);

// "Title (family-id)" for family lists.
QString familyText(const dev::Dictionary &dictionary);
// An HCS mode with its E00 label, "3 — Closed loop one valve"; other modes as listed ("vpoc").
QString modeText(const dev::Dictionary &dictionary, const std::string &mode);

} // namespace vt::ui
