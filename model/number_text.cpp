#include "number_text.h"

#include "dict/cooking.h"

#include <QCoreApplication>
#include <QLocale>
#include <algorithm>
#include <cmath>

namespace vt::model {
namespace {

// The context of this file's sentences in the catalogue.
class NumberText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::NumberText)
};

QChar decimalSign(dev::Language lang)
{
    return lang == dev::Language::German ? QLatin1Char(',') : QLatin1Char('.');
}

QString example(int decimals, dev::Language lang)
{
    return decimals > 0 ? formatNumber(1.5, std::max(1, std::min(decimals, 2)), lang)
                        : QStringLiteral("15");
}

QString withUnit(const QString &number, const QString &unit)
{
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

QString notationRefusal(const QString &typed, int decimals, dev::Language lang)
{
    if (decimals == 0)
        return NumberText::tr("“%1” is not a whole number as typed here: digits only, no thousands "
                              "separators and no exponent, e.g. %2.")
            .arg(typed, example(0, lang));
    return NumberText::tr(
               "“%1” is not a number as typed here: digits with “%2” as the decimal sign, no "
               "thousands separators and no exponent, e.g. %3.")
        .arg(typed, QString(decimalSign(lang)), example(decimals, lang));
}

// The displayed number of digits after the decimal sign, as dev::formatNumber shows the row.
int displayDecimals(const dev::ParamMeta &row)
{
    return row.scale.name.empty() && row.isFloat() ? 3 : row.scale.decimals;
}

} // namespace

QString formatNumber(double value, int decimals, dev::Language lang)
{
    if (!std::isfinite(value))
        return QStringLiteral("–");
    decimals = std::clamp(decimals, 0, 9);
    QString text = QLocale::c().toString(value, 'f', decimals);
    if (text.startsWith(QLatin1Char('-')) &&
        text.mid(1).count(QLatin1Char('0')) + text.count(QLatin1Char('.')) == text.size() - 1)
        text.remove(0, 1); // no "-0,0"
    if (lang == dev::Language::German)
        text.replace(QLatin1Char('.'), QLatin1Char(','));
    return text;
}

NumberParse parseNumber(const QString &text, dev::Language lang, const NumberRules &rules)
{
    const QString typed = text.trimmed();
    if (typed.isEmpty())
        return {std::nullopt, NumberText::tr("No number entered; type one like %1.")
                                  .arg(example(rules.decimals, lang))};
    QString number = typed;
    if (!rules.unit.isEmpty() && number.size() > rules.unit.size() &&
        number.endsWith(rules.unit, Qt::CaseInsensitive))
        number = number.chopped(rules.unit.size()).trimmed();

    // sign? digits+ (decimal-sign digits+)?
    qsizetype at = 0;
    const bool negative = at < number.size() && number.at(at) == QLatin1Char('-');
    if (at < number.size() &&
        (number.at(at) == QLatin1Char('-') || number.at(at) == QLatin1Char('+')))
        ++at;
    const qsizetype wholeStart = at;
    while (at < number.size() && number.at(at) >= QLatin1Char('0') &&
           number.at(at) <= QLatin1Char('9'))
        ++at;
    const QString whole = number.mid(wholeStart, at - wholeStart);
    QString fraction;
    bool hasSign = false;
    if (at < number.size() && number.at(at) == decimalSign(lang)) {
        hasSign = true;
        const qsizetype fractionStart = ++at;
        while (at < number.size() && number.at(at) >= QLatin1Char('0') &&
               number.at(at) <= QLatin1Char('9'))
            ++at;
        fraction = number.mid(fractionStart, at - fractionStart);
    }
    if (whole.isEmpty() || at != number.size() || (hasSign && fraction.isEmpty()))
        return {std::nullopt, notationRefusal(typed, rules.decimals, lang)};

    // More digits than the field keeps would be rounded away: refused unless they are zeros.
    QString significant = fraction;
    while (significant.size() > rules.decimals && significant.endsWith(QLatin1Char('0')))
        significant.chop(1);
    if (significant.size() > rules.decimals) {
        if (rules.decimals == 0)
            return {std::nullopt,
                    NumberText::tr("“%1” is not a whole number; this field takes whole numbers "
                                   "only, e.g. %2.")
                        .arg(typed, example(0, lang))};
        return {std::nullopt,
                NumberText::tr("“%1” has more than %2 digits after the decimal sign; it is not "
                               "rounded. Type at most %2, e.g. %3.")
                    .arg(typed, QString::number(rules.decimals), example(rules.decimals, lang))};
    }

    const QString canonical = (negative ? QStringLiteral("-") : QString()) + whole +
                              (significant.isEmpty() ? QString() : QLatin1Char('.') + significant);
    bool ok = false;
    double value = QLocale::c().toDouble(canonical, &ok);
    if (!ok || !std::isfinite(value))
        return {std::nullopt, notationRefusal(typed, rules.decimals, lang)};
    if (value == 0)
        value = 0; // no -0
    if (value < rules.minimum || value > rules.maximum) {
        const QString min =
            std::isfinite(rules.minimum)
                ? withUnit(formatNumber(rules.minimum, rules.decimals, lang), rules.unit)
                : QStringLiteral("−∞");
        const QString max =
            std::isfinite(rules.maximum)
                ? withUnit(formatNumber(rules.maximum, rules.decimals, lang), rules.unit)
                : QStringLiteral("∞");
        return {std::nullopt,
                NumberText::tr("%1 is outside the allowed range %2 … %3.")
                    .arg(withUnit(formatNumber(value, static_cast<int>(significant.size()), lang),
                                  rules.unit),
                         min, max)};
    }
    return {value, QString()};
}

ParamParse parseParamValue(const dev::ParamMeta &row, const QString &text, dev::Language lang)
{
    const QString typed = text.trimmed();
    const bool isLabel = std::any_of(row.enums.begin(), row.enums.end(), [&](const auto &e) {
        return typed.compare(QString::fromStdString(e.text.en), Qt::CaseInsensitive) == 0 ||
               typed.compare(QString::fromStdString(e.text.de), Qt::CaseInsensitive) == 0;
    });
    if (isLabel) {
        auto parsed = dev::parseValue(row, typed.toStdString(), lang);
        if (!parsed)
            return {std::nullopt, QString::fromStdString(parsed.error().message.in(lang))};
        return {*parsed, QString()};
    }
    const dev::Limits limits = dev::rowLimits(row);
    const double a = dev::toDisplay(row, limits.min);
    const double b = dev::toDisplay(row, limits.max);
    NumberRules rules;
    rules.decimals = displayDecimals(row);
    rules.minimum = std::min(a, b);
    rules.maximum = std::max(a, b);
    rules.unit = QString::fromStdString(row.unit);
    const NumberParse number = parseNumber(typed, lang, rules);
    if (!number.ok())
        return {std::nullopt, number.refusal};
    // The dictionary's cooking turns the exact display value into the raw step (and keeps the
    // scale's own rounding rule, e.g. the DSP-408 truncation).
    auto parsed =
        dev::parseValue(row, formatNumber(*number.value, rules.decimals, lang).toStdString(), lang);
    if (!parsed)
        return {std::nullopt, QString::fromStdString(parsed.error().message.in(lang))};
    return {*parsed, QString()};
}

} // namespace vt::model
