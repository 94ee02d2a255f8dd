// CSV export of one module's values, for spreadsheets and commissioning
// reports: name, label, value, unit, raw, range, access. English files use ',' between fields and
// '.' as decimal sign, German ones ';' and ',' (what spreadsheets expect in each locale); the
// header comment states both. One-way: files are read back from .vtpar, never from CSV. Pure,
// any thread.
#pragma once

#include "core/local_text.h"
#include "dict/dictionary.h"
#include "param_file.h"

#include <string>

namespace vt::dev::files {

struct CsvOptions
{
    Language lang = Language::English;
    bool byteOrderMark = false; // UTF-8 BOM first: lets Excel recognise UTF-8 (umlauts in labels)
};

char csvSeparator(Language lang);   // ',' / ';'
char csvDecimalSign(Language lang); // '.' / ','

// One field, quoted when needed (RFC 4180): separator, quote, CR/LF, leading or trailing space,
// a leading '#' (it would read as a comment). A text that a spreadsheet would run as a formula
// ('=', '+', '@', or '-' not followed by a digit) gets a leading apostrophe.
std::string csvField(const std::string &text, char separator);

// `dict` may be null (no labels, units, ranges; rows as the file holds them). Lines end in CRLF.
std::string exportCsv(const ModuleRecord &record, const Dictionary *dict,
                      const CsvOptions &options = {});

} // namespace vt::dev::files
