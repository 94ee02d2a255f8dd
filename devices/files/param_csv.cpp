#include "param_csv.h"

#include "dict/cooking.h"
#include "param_file_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vt::dev::files {
namespace {

// Beyond this formatNumber would lose digits (and enum lookup casts to an integer).
constexpr double kDisplayLimit = 1e15;

// User texts in the comment lines must not split them into cells.
std::string commentSafe(std::string text, char separator)
{
    for (char &c : text) {
        if (c == '\r' || c == '\n' || c == '"')
            c = ' ';
        else if (c == separator)
            c = separator == ',' ? ';' : ',';
    }
    return text;
}

std::string localNumber(double raw, Language lang)
{
    std::string s = rawNumberText(raw);
    if (lang == Language::German)
        std::replace(s.begin(), s.end(), '.', ',');
    return s;
}

bool displayable(double v)
{
    return std::isfinite(v) && std::fabs(v) <= kDisplayLimit;
}

struct Cells
{
    std::string label, value, unit, raw, range, access;
};

Cells cellsFor(const ValueRow &row, const ParamMeta *meta, Language lang)
{
    Cells c;
    c.raw =
        isText(row.raw) ? std::get<std::string>(row.raw) : localNumber(rawNumber(row.raw), lang);
    if (!meta || meta->isString() != isText(row.raw)) {
        c.value = row.display; // no dictionary row fits: what the file says, for people
        if (meta)
            c.label = meta->label.in(lang);
        return c;
    }
    c.label = meta->label.in(lang);
    c.access = accessText(meta->access).in(lang);
    if (meta->isString()) {
        c.value = c.raw;
        if (meta->length > 0)
            c.range = (lang == Language::German ? "≤ " + std::to_string(meta->length) + " Bytes"
                                                : "≤ " + std::to_string(meta->length) + " bytes");
        return c;
    }
    c.unit = meta->unit;
    const double v = rawNumber(row.raw);
    if (displayable(v)) {
        const EnumLabel *e =
            v == std::floor(v) ? meta->findEnum(static_cast<std::int64_t>(v)) : nullptr;
        c.value = e ? e->text.in(lang) : formatNumber(*meta, v, lang);
    }
    const bool typeRange = meta->min <= typeMin(meta->type) && meta->max >= typeMax(meta->type);
    if (!(meta->isFloat() && typeRange) && displayable(meta->min) && displayable(meta->max))
        c.range =
            formatNumber(*meta, meta->min, lang) + " … " + formatNumber(*meta, meta->max, lang);
    return c;
}

} // namespace

char csvSeparator(Language lang)
{
    return lang == Language::German ? ';' : ',';
}
char csvDecimalSign(Language lang)
{
    return lang == Language::German ? ',' : '.';
}

std::string csvField(const std::string &text, char separator)
{
    std::string s = text;
    if (!s.empty()) {
        const char first = s.front();
        const bool dashWord = first == '-' && (s.size() < 2 || s[1] < '0' || s[1] > '9');
        if (first == '=' || first == '+' || first == '@' || first == '\t' || dashWord)
            s.insert(0, 1, '\'');
    }
    const bool quote =
        s.find_first_of(std::string{separator, '"', '\r', '\n'}) != std::string::npos ||
        (!s.empty() && (s.front() == ' ' || s.back() == ' ' || s.front() == '#'));
    if (!quote)
        return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + "\"";
}

std::string exportCsv(const ModuleRecord &record, const Dictionary *dict, const CsvOptions &options)
{
    const Language lang = options.lang;
    const bool de = lang == Language::German;
    const char sep = csvSeparator(lang);
    std::string out = options.byteOrderMark ? "\xEF\xBB\xBF" : "";
    out += de ? "# ValveTune-Parameterexport. Trennzeichen: Semikolon. Dezimalzeichen: Komma. "
                "Kodierung: UTF-8.\r\n"
              : "# ValveTune parameter export. Separator: comma. Decimal sign: point. Encoding: "
                "UTF-8.\r\n";
    std::string module =
        (de ? "# Modul " : "# Module ") + std::to_string(record.address) + ": " + record.family;
    if (!record.version.empty())
        module += ". Version " + record.version;
    if (!record.mode.empty())
        module += (de ? ". Modus " : ". Mode ") + record.mode;
    if (!record.label.empty())
        module += (de ? ". Bezeichnung: " : ". Label: ") + record.label;
    out += commentSafe(module, sep) + "\r\n";

    const std::vector<std::string> header =
        de ? std::vector<std::string>{"Name",    "Bezeichnung", "Wert",   "Einheit",
                                      "Rohwert", "Bereich",     "Zugriff"}
           : std::vector<std::string>{"Name", "Label", "Value", "Unit", "Raw", "Range", "Access"};
    for (std::size_t i = 0; i < header.size(); ++i)
        out += (i ? std::string(1, sep) : std::string()) + header[i];
    out += "\r\n";

    for (const ValueRow &row : record.values) {
        const ParamMeta *meta = dict ? findMeta(*dict, row) : nullptr;
        const Cells c = cellsFor(row, meta, lang);
        for (const std::string *field :
             {&row.name, &c.label, &c.value, &c.unit, &c.raw, &c.range, &c.access}) {
            if (field != &row.name)
                out += sep;
            out += csvField(*field, sep);
        }
        out += "\r\n";
    }
    return out;
}

} // namespace vt::dev::files
