// The options every valvetune-cli device command shares: the connection (app/cmdline/
// connection_options.h, the parser valvetune --connect uses too), which module (--module) and
// the display language (--lang). Pure parsing; any thread.
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "model/session/connection.h"

#include <QStringList>
#include <optional>
#include <string>

namespace vt::cli {

struct DeviceOptions
{
    model::ConnectionSpec spec;
    std::optional<int> module; // --module ADDRESS
    dev::Language lang = dev::Language::English;
};

// The options' synopsis for usage texts.
std::string deviceSynopsis();

// Removes the shared options from `args` (the command's own options stay). The error is a
// usage message (exit 2).
dev::Result<DeviceOptions, std::string> takeDeviceOptions(QStringList &args);

// The first argument left that looks like an option ("--frobnicate"), for "unknown option".
std::optional<QString> leftoverOption(const QStringList &args);

} // namespace vt::cli
