// The device's own texts — HART tag, long tag, descriptor, date and message (HART-7 manual §5.1.10,
// §5.1.11, §5.1.18: commands 12, 13, 20) — as one list for the node view and `valvetune-cli info`.
// Pure functions; any thread.
#pragma once

#include "dict/dictionary.h"
#include "dict/raw_value.h"

#include <QCoreApplication>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

namespace vt::model {

struct IdentityText
{
    std::string key;    // "tag", "long_tag", "descriptor", "date", "message" (for --json)
    QString label;      // "Tag", "Date"
    QString value;      // as the device holds it
    bool known = false; // read (an empty text that was read is known)
};

// The rows the texts come from (the date as its three rows); empty for families without them.
std::vector<const dev::ParamMeta *> identityTextRows(const dev::Dictionary &dictionary);

// The texts of `dictionary` with the values `valueOf` knows (nullopt: not read).
std::vector<IdentityText>
identityTexts(const dev::Dictionary &dictionary,
              const std::function<std::optional<dev::RawValue>(const dev::ParamMeta *)> &valueOf,
              dev::Language lang);

} // namespace vt::model
