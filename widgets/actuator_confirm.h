// The one question before a write that can move the actuator (set values, the set-value source,
// control words): which module, which parameter, old → new value. Every window that sends such
// a write asks through here; tests answer through the hook instead of a dialog.
#pragma once

#include "core/local_text.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

class QWidget;

namespace vt::ui {

// "Module 2: A1.01 (Bus set value 1) 0.000 V → 2.000 V"; "?" for an unknown old value.
QString actuatorWriteLine(int module, const dev::ParamMeta &row,
                          const std::optional<dev::RawValue> &before, const dev::RawValue &after,
                          dev::Language lang);

// Asks the person (window-modal, non-blocking); `yes` runs only when they agree, `no` (when
// given) when they do not.
void confirmActuatorWrites(QWidget *parent, const QStringList &lines, std::function<void()> yes,
                           std::function<void()> no = {});

// Asks whether to put back what the tool changed (default: yes); `answer(true)` to put back.
void askRestoreActuators(QWidget *parent, const QString &when, const QStringList &lines,
                         std::function<void(bool)> answer);

// Tests: answer every question without a dialog (`lines` as asked). Unset to ask again.
using ActuatorAnswerHook = std::function<bool(const QStringList &lines)>;
void setActuatorAnswerHook(ActuatorAnswerHook hook);

} // namespace vt::ui
