// The options of the ED1's PROFIBUS image over TCP (dsp408-image, dsp408-gateway) that
// valvetune-cli, `valvetune --connect` and valvetune-sim share, so a master and the simulator
// are configured with the same words: where the gateway maps the images (--out-register,
// --in-register, --in-function 3|4), how a register holds two image bytes (--register-bytes),
// the PZD word order of 32-bit values (--pzd-words) and the PKW IND byte (--ind-byte).
// ARCHITECTURE.md "Byte order": the worked examples' layout is the default.
// Pure parsing; any thread.
#pragma once

#include "access/dsp408_adapter.h"

#include <QString>
#include <array>
#include <optional>
#include <string>

namespace vt::cmdline {

inline constexpr std::array<const char *, 6> kDsp408Options{"--out-register", "--in-register",
                                                            "--pzd-words",    "--register-bytes",
                                                            "--in-function",  "--ind-byte"};

// One line for usage texts (no trailing newline).
extern const char kDsp408Synopsis[];

// Applies `--name value` to `options`; an English one-line error for a value it refuses.
std::optional<std::string> applyDsp408Option(const QString &name, const QString &value,
                                             dev::access::Dsp408LinkOptions &options);

} // namespace vt::cmdline
