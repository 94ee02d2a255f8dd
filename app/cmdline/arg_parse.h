// Small helpers for the command lines of valvetune-cli and valvetune: "--name value" options and
// numbers in the notations PLC programmers use (1000, -3000, 0x03E8).
#pragma once

#include <QStringList>
#include <cstdint>
#include <optional>
#include <string>

namespace vt::cmdline {

// Removes "--name value" from args and returns the value; "" when absent. Sets `missing` when the
// option is the last word (no value).
std::optional<QString> takeOption(QStringList &args, const QString &name, bool *missing);
bool takeFlag(QStringList &args, const QString &name);

// Integer in decimal or 0x hex within [min, max]; nullopt otherwise.
std::optional<long long> parseInteger(const QString &text, long long min, long long max);

} // namespace vt::cmdline
