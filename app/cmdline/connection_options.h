// The connection options valvetune-cli's device commands and `valvetune --connect` share: where
// the device is (--sim, --port, --tcp, --can, --hart and their settings) and how to talk to it
// (--unit, --fault, --product, --turnaround), parsed into the model::ConnectionSpec the GUI's
// connect dialog builds too. One parser for both programs. Pure parsing; any thread.
#pragma once

#include "core/result.h"
#include "model/session/connection.h"

#include <QStringList>
#include <string>

namespace vt::cmdline {

// The options' synopsis for usage and help texts (no trailing newline).
extern const char kConnectionSynopsis[];

// Whether `args` hold one of the options takeConnectionOptions() takes.
bool hasConnectionOption(const QStringList &args);

// Removes the connection options from `args` (everything else stays). The error is one English
// line for a usage message.
dev::Result<model::ConnectionSpec, std::string> takeConnectionOptions(QStringList &args);

} // namespace vt::cmdline
