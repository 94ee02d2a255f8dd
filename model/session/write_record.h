// WriteRecord: what a safe write did to each parameter — the precise record a commissioning
// engineer needs after a cable was pulled mid-write: which values are verified on the device,
// which may or may not have arrived, which were never sent. A plain value; any thread.
#pragma once

#include "core/local_text.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"
#include "model/sentence.h"

#include <QString>
#include <optional>
#include <vector>

namespace vt::model {

enum class WriteStatus {
    Pending,        // not yet attempted
    Unchanged,      // the device already holds the value: nothing sent
    RefusedLocally, // out of range or not writable: never sent (the text names the limits)
    Verified,       // written and read back equal
    Written,        // acknowledged, not read back (write-only row)
    Refused,        // the device answered with an exception (deviceText = its text)
    Mismatch,       // acknowledged, but the read back differs (reason says what came back)
    Uncertain,      // sent without an answer: it may or may not be on the device
    NotSent,        // the job stopped before this row
};

struct WriteItem
{
    const dev::ParamMeta *row = nullptr;
    dev::RawValue value;                 // what should be on the device
    std::optional<dev::RawValue> before; // what the device held, when known
    WriteStatus status = WriteStatus::Pending;
    std::optional<dev::RawValue> readBack;
    int exceptionCode = 0;
    Sentence reason;           // the application's words, said when shown
    dev::LocalText deviceText; // the device's or the dictionary's words (a refusal, a range
                               // error), both languages; shown through writeReasonText()
};

// True for statuses after which the device holds `value` for sure.
inline bool isOnDevice(WriteStatus s)
{
    return s == WriteStatus::Verified || s == WriteStatus::Unchanged || s == WriteStatus::Written;
}
// True for statuses a resume() takes up again.
inline bool needsResume(WriteStatus s)
{
    return s == WriteStatus::Pending || s == WriteStatus::Uncertain || s == WriteStatus::NotSent ||
           s == WriteStatus::Mismatch;
}

QString writeStatusText(WriteStatus status);
Sentence writeStatusSentence(WriteStatus status); // the same, said when shown
// Why a row ended as it did, in `lang`: the device's or dictionary's text when there is one,
// otherwise the application's reason. Empty when there is nothing to say.
QString writeReasonText(const WriteItem &item, dev::Language lang);
// The same kept as a sentence, for a text that stays on screen across a language switch.
Sentence writeReason(const WriteItem &item);
// "verified", "refused: value out of range" … for the CLI and the result list.
const char *writeStatusKey(WriteStatus status);

} // namespace vt::model
