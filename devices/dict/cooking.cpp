#include "cooking.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace vt::dev {
namespace {

char decimalSign(Language lang)
{
    return lang == Language::German ? ',' : '.';
}

std::string trim(std::string_view s)
{
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
        ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
        --e;
    return std::string(s.substr(b, e - b));
}

bool equalsIgnoreCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

int displayDecimals(const ParamMeta &meta)
{
    return meta.scale.name.empty() && meta.isFloat() ? 3 : meta.scale.decimals;
}

std::string formatDisplayNumber(double v, int decimals, Language lang)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s == "-0" || (s.rfind("-0.", 0) == 0 && s.find_first_not_of("-0.") == std::string::npos))
        s.erase(0, 1); // no "-0.000"
    std::replace(s.begin(), s.end(), '.', decimalSign(lang));
    return s;
}

CookError rangeError(const ParamMeta &meta, CookError::Kind kind, double limitRaw)
{
    const std::string en = formatValue(meta, limitRaw, Language::English);
    const std::string de = formatValue(meta, limitRaw, Language::German);
    const Limits l = rowLimits(meta);
    const std::string rangeEn = formatValue(meta, l.min, Language::English) + " … " +
                                formatValue(meta, l.max, Language::English);
    const std::string rangeDe = formatValue(meta, l.min, Language::German) + " … " +
                                formatValue(meta, l.max, Language::German);
    if (kind == CookError::Kind::BelowMin)
        return {kind,
                {meta.name + ": below the minimum " + en + " (range " + rangeEn + ")",
                 meta.name + ": unter dem Minimum " + de + " (Bereich " + rangeDe + ")"}};
    return {kind,
            {meta.name + ": above the maximum " + en + " (range " + rangeEn + ")",
             meta.name + ": über dem Maximum " + de + " (Bereich " + rangeDe + ")"}};
}

} // namespace

Limits rowLimits(const ParamMeta &meta)
{
    return {meta.min, meta.max};
}

double toDisplay(const ParamMeta &meta, double raw)
{
    const double v = meta.scale.name.empty() ? raw : raw * meta.scale.factor;
    const double p = std::pow(10.0, displayDecimals(meta));
    return std::round(v * p) / p;
}

std::string formatNumber(const ParamMeta &meta, double raw, Language lang)
{
    if (meta.scale.name.empty() && !meta.isFloat())
        return formatDisplayNumber(raw, 0, lang);
    return formatDisplayNumber(toDisplay(meta, raw), displayDecimals(meta), lang);
}

std::string formatValue(const ParamMeta &meta, double raw, Language lang)
{
    if (const EnumLabel *e = meta.findEnum(static_cast<std::int64_t>(raw));
        e && raw == std::floor(raw))
        return e->text.in(lang);
    std::string s = formatNumber(meta, raw, lang);
    if (!meta.unit.empty())
        s += " " + meta.unit;
    return s;
}

std::string formatBits(const ParamMeta &meta, std::uint32_t raw, Language lang)
{
    std::string out;
    for (int bit = 0; bit < 32; ++bit) {
        if (!(raw & (1u << bit)))
            continue;
        const auto it = std::find_if(meta.bits.begin(), meta.bits.end(),
                                     [&](const BitLabel &b) { return b.bit == bit; });
        if (!out.empty())
            out += ", ";
        out += it != meta.bits.end()
                   ? it->text.in(lang)
                   : (lang == Language::German ? "Bit " : "bit ") + std::to_string(bit);
    }
    return out;
}

std::optional<CookError> checkWrite(const ParamMeta &meta, double raw, std::optional<Limits> limits)
{
    if (!meta.writable())
        return CookError{
            CookError::Kind::NotWritable,
            {meta.name + " cannot be written (" + accessText(meta.access).en + ")",
             meta.name + " ist nicht schreibbar (" + accessText(meta.access).de + ")"}};
    return checkRange(meta, raw, limits);
}

std::optional<CookError> checkRange(const ParamMeta &meta, double raw, std::optional<Limits> limits)
{
    const Limits l = limits.value_or(rowLimits(meta));
    if (!std::isfinite(raw) || raw < l.min)
        return rangeError(meta, CookError::Kind::BelowMin, l.min);
    if (raw > l.max)
        return rangeError(meta, CookError::Kind::AboveMax, l.max);
    return std::nullopt;
}

Result<double, CookError> parseValue(const ParamMeta &meta, std::string_view input, Language lang,
                                     std::optional<Limits> limits)
{
    std::string text = trim(input);
    if (text.empty())
        return CookError{CookError::Kind::Empty, {"no value entered", "kein Wert eingegeben"}};

    for (const EnumLabel &e : meta.enums) {
        if (equalsIgnoreCase(text, e.text.en) || equalsIgnoreCase(text, e.text.de)) {
            const auto raw = static_cast<double>(e.value);
            if (auto err = checkRange(meta, raw, limits))
                return *err;
            return raw;
        }
    }
    if (!meta.unit.empty() && text.size() > meta.unit.size() &&
        equalsIgnoreCase(std::string_view(text).substr(text.size() - meta.unit.size()), meta.unit))
        text = trim(std::string_view(text).substr(0, text.size() - meta.unit.size()));

    const char own = decimalSign(lang);
    const char other = lang == Language::German ? '.' : ',';
    if (text.find(other) != std::string::npos)
        return CookError{CookError::Kind::WrongDecimalSign,
                         {std::string("use '") + own + "' as the decimal sign",
                          std::string("Dezimalzeichen ist '") + own + "'"}};
    std::replace(text.begin(), text.end(), own, '.');
    if (!text.empty() && text.front() == '+')
        text.erase(0, 1);
    double typed = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), typed);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(typed)) {
        if (!meta.enums.empty())
            return CookError{
                CookError::Kind::UnknownLabel,
                {"'" + trim(input) + "' is neither a number nor a label of " + meta.name,
                 "'" + trim(input) + "' ist weder eine Zahl noch eine Auswahl von " + meta.name}};
        return CookError{
            CookError::Kind::NotANumber,
            {"'" + trim(input) + "' is not a number", "'" + trim(input) + "' ist keine Zahl"}};
    }

    double raw = typed;
    if (!meta.scale.name.empty()) {
        const double steps = typed / meta.scale.factor;
        if (meta.scale.rounding == Rounding::Truncate) {
            // Half a display digit of tolerance: a shown (rounded) value maps back to its step.
            const double halfDigit = 0.5 * std::pow(10.0, -meta.scale.decimals) / meta.scale.factor;
            raw = std::trunc(steps + std::copysign(halfDigit * 0.999, steps));
        } else {
            raw = std::round(steps);
        }
    } else if (!meta.isFloat()) {
        if (typed != std::floor(typed))
            return CookError{
                CookError::Kind::NotANumber,
                {meta.name + " takes whole numbers only", meta.name + " nimmt nur ganze Zahlen"}};
    }
    if (raw == 0)
        raw = 0; // no -0
    if (auto err = checkRange(meta, raw, limits))
        return *err;
    return raw;
}

} // namespace vt::dev
