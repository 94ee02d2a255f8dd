// How valvetune-cli's device commands print values, modules and write results: one text line per
// value for people ("C1.07         1.000 V"), stable JSON objects for scripts
// ({"name", "raw", "display", "unit"}), and the exit code a failed exchange or write maps to.
// Pure functions; the CLI's thread.
#pragma once

#include "core/local_text.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"
#include "model/session/device_access.h"
#include "model/session/write_record.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace vt::cli {

using Json = nlohmann::ordered_json;

std::string str(const QString &text);
// "1.500" with `decimals` decimals (C notation, for logs and tables); "-" when not finite.
std::string fixed(double v, int decimals);
// A number, or null when it is not finite (JSON has no NaN).
Json numberOrNull(double v);
// A number typed in the language's notation ("1.5", German "1,5"), refusing the other language's
// decimal sign; nullopt when it is not a finite number.
std::optional<double> parseDecimal(const QString &text, dev::Language lang);
// "valvetune-cli: warning: module 0: hart_DeviceSpecificStatus: status bytes mismatch … (14)" on
// `err` for each value that arrived with a device warning (HART-7 manual §4.4.1 "Status").
void printWarnings(std::ostream &err, int module, const std::vector<model::RowValue> &values,
                   dev::Language lang);

// A raw value as JSON: integers as integers, other numbers as numbers, text as a string.
Json rawJson(const dev::RawValue &value);
// "1.000 V", "off", "\"VALVE1\"" in `lang`.
std::string displayOf(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang);
// {"name", "raw", "display", "unit"}
Json valueJson(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang);
// "C1.07         1.000 V"
void printValue(std::ostream &out, const dev::ParamMeta &row, const dev::RawValue &value,
                dev::Language lang, const std::string &indent = {});
// Equal as the device stores them: float32 rows compared as float, text without trailing blanks.
bool sameValue(const dev::ParamMeta &row, const dev::RawValue &a, const dev::RawValue &b);

// {"address", "family", "version", "mode", "exact", "warning"}
Json moduleJson(const model::ModuleInfo &module);
// "module 1: dma-pn-v51 V51.03, mode 3" (`noun` "address": "address 1: …")
std::string moduleText(const model::ModuleInfo &module, const char *noun = "module");

// Why an exchange failed, for people: the device's exception text in `lang` or the session's
// reason.
std::string outcomeText(const model::Outcome &outcome, dev::Language lang);
// Link lost: 3; the device refused or did not answer: 1.
int exitCodeOf(const model::Outcome &outcome);

// {"name", "value", "before", "status", "reason", "read_back"} (values as valueJson, or null)
Json writeItemJson(const model::WriteItem &item, dev::Language lang);
// "C1.07         0.000 V -> 1.000 V  verified"
void printWriteItem(std::ostream &out, const model::WriteItem &item, dev::Language lang);
// The exit code of a finished write: 3 link lost, 4 a read back differs, 1 refused by the device
// (or not finished), 2 refused before sending, else 0.
int exitCodeOf(const std::vector<model::WriteItem> &items, bool linkLost);

} // namespace vt::cli
