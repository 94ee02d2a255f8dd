// The parameter blocks as the manuals group them: their order in the editor and their titles
// (HCS: d display, C controller, E settings …; Wandfluh: the function blocks of the ED1/SD1 and
// SD7 manuals). Titles are translated at call time.
#pragma once

#include "dict/dictionary.h"

#include <QString>
#include <string>
#include <vector>

namespace vt::model {

// The blocks of a dictionary in display order: HCS d C E A L r S B system, then any other in
// the order the dictionary first uses them.
std::vector<std::string> blockOrder(const dev::Dictionary &dictionary);
// "Display values", "Controller" …; the key itself for a block without a known title.
QString blockTitle(const std::string &block);

} // namespace vt::model
