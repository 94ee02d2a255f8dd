// Linked navigation between the telegram log and the parameters. A request names its
// parameters; an answer belongs to the request of its module just before it.
// Pure functions over a TelegramLog; GUI thread (the log's).
#pragma once

#include "hcs/types.h"
#include "inspect/frame_parameters.h"
#include "model/telegrams/telegram_log.h"

#include <QList>
#include <QStringList>

namespace vt::dev {
struct Dictionary;
}

namespace vt::model {

// The request record a record belongs to: itself for a request, else the latest earlier request
// of the same module (nullopt when there is none or it is gone).
std::optional<quint64> requestSeqOf(const TelegramLog &log, quint64 seq);

// Names of the dictionary parameters the record's exchange addresses, in frame order; the ED1's
// frames read with the link's `layout`.
QStringList parametersOfRecord(const TelegramLog &log, quint64 seq,
                               const vt::dev::Dictionary &dictionary,
                               vt::dev::hcs::Family family = vt::dev::hcs::Family::Dma,
                               const vt::dev::inspect::ImageLayout &layout = {});

// The newest exchange that carried `parameterName` to / from `module` (-1 = any module): the
// request's seq and the seqs of the records answering it (replies, timeouts). Empty when none.
QList<quint64> lastFramesFor(const TelegramLog &log, int module, const QString &parameterName,
                             const vt::dev::Dictionary &dictionary,
                             vt::dev::hcs::Family family = vt::dev::hcs::Family::Dma,
                             const vt::dev::inspect::ImageLayout &layout = {});

} // namespace vt::model
