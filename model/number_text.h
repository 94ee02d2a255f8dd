// Numbers as a person types and reads them in the UI language: the one exact parser and the one
// formatter behind every numeric input of the GUI (editor, monitor, curve, fold wizard,
// inspector, connect dialog). German "1,5" and English "1.5" are 1.5; anything that is not
// exactly a number in the language's notation ("1,5" in English, "1.500,25", "1e3") is refused
// with a sentence that names the notation — never truncated, rounded or read another way.
// Pure functions; the refusal sentences are in the installed translation, so call them on the
// GUI thread.
#pragma once

#include "core/local_text.h"
#include "dict/param_meta.h"

#include <QString>
#include <limits>
#include <optional>

namespace vt::model {

struct NumberRules
{
    int decimals = 0; // digits allowed after the decimal sign; 0: whole numbers only
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();
    QString unit; // may follow the number ("1,5 V"); named in the range sentence
};

struct NumberParse
{
    std::optional<double> value;
    QString refusal; // whole sentence in the UI language when value is empty

    bool ok() const { return value.has_value(); }
};

// Exactly: optional sign, digits, optionally the language's decimal sign and at most
// rules.decimals digits (more are accepted only as trailing zeros), optionally the unit;
// then the range. No thousands separators, no exponent, no other decimal sign.
NumberParse parseNumber(const QString &text, dev::Language lang, const NumberRules &rules);

// `value` rounded to `decimals` digits in the language's notation, without thousands
// separators, so that parseNumber reads it back: formatNumber(1.5, 3, German) = "1,500".
QString formatNumber(double value, int decimals, dev::Language lang);

// A parameter's value typed in the editor: one of its labels, or a number exactly as parseNumber
// reads it (display decimals, unit and range of the row), converted to the raw value by the
// dictionary's cooking. The refusal does not repeat the parameter's name.
struct ParamParse
{
    std::optional<double> raw;
    QString refusal;
};
ParamParse parseParamValue(const dev::ParamMeta &row, const QString &text, dev::Language lang);

} // namespace vt::model
