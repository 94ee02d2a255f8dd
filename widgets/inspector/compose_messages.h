// What the composer says and follows, as plain functions over its data: a field refused as the
// panel labels it, the answer to a sent frame decoded as the telegram list decodes it, the frame
// a link can send, and the parameter a composed write changes. GUI thread (they call tr()).
#pragma once

#include "core/field_span.h"
#include "core/link_protocol.h"
#include "dict/dictionary.h"
#include "inspect/compose.h"
#include "model/session/session.h"

#include <QString>
#include <functional>
#include <optional>

namespace vt::ui {

// "Count must be 1 to 8." with `labelOf(field key)` the panel's label ("" = none: the codec's
// English reason).
QString composeRefusalText(const dev::inspect::ComposeError &error,
                           const std::function<QString(const QString &key)> &labelOf);

// A read in the link's own protocol: the frame the composer offers first on a connection.
std::optional<dev::inspect::ComposeKind> readKindFor(dev::LinkProtocol link);

// The answer to a sent frame: decoded (how the link carries it, the request's first register for
// a read's data words) when it decodes; nullopt for no answer or bytes that do not decode.
std::optional<dev::Description> decodeAnswer(const model::Outcome &outcome, dev::LinkProtocol link,
                                             const dev::inspect::ComposeSpec &request,
                                             const dev::Dictionary *dictionary);

// The result line for the outcome, rendered in the language of the moment: "Answered: <summary>
// (hex)", or what went wrong.
std::function<QString()> answerText(const model::Outcome &outcome,
                                    const std::optional<dev::Description> &decoded);

// The row of `dictionary` a composed write changes (by ID, IND/PNU/instance or SDO object), so
// that it is read back and journalled; nullptr for a read or an address no row has.
const dev::ParamMeta *rowWrittenBy(const dev::Dictionary *dictionary,
                                   const dev::inspect::ComposeSpec &spec);

} // namespace vt::ui
