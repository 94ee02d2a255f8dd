#include "device_output.h"

#include "dict/cooking.h"
#include "exit_codes.h"

#include <QLocale>
#include <cmath>
#include <cstdio>
#include <iomanip>

namespace vt::cli {

namespace {

constexpr int kNameWidth = 14;

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0'))
        s.pop_back();
    return s;
}

Json optionalValue(const dev::ParamMeta &row, const std::optional<dev::RawValue> &value,
                   dev::Language lang)
{
    if (!value)
        return nullptr;
    return Json{{"raw", rawJson(*value)}, {"display", displayOf(row, *value, lang)}};
}

} // namespace

std::string str(const QString &text)
{
    return text.toStdString();
}

Json rawJson(const dev::RawValue &value)
{
    if (dev::isText(value))
        return std::get<std::string>(value);
    const double v = dev::rawNumber(value);
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15)
        return static_cast<long long>(v);
    if (!std::isfinite(v))
        return std::isnan(v) ? "NaN" : (v > 0 ? "Infinity" : "-Infinity");
    return v;
}

std::string displayOf(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    if (dev::isText(value))
        return "\"" + trimmed(std::get<std::string>(value)) + "\"";
    return dev::formatValue(row, dev::rawNumber(value), lang);
}

Json valueJson(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    return Json{{"name", row.name},
                {"raw", rawJson(value)},
                {"display", displayOf(row, value, lang)},
                {"unit", row.unit}};
}

void printValue(std::ostream &out, const dev::ParamMeta &row, const dev::RawValue &value,
                dev::Language lang, const std::string &indent)
{
    out << indent << std::left << std::setw(kNameWidth) << row.name << ' '
        << displayOf(row, value, lang) << '\n';
}

bool sameValue(const dev::ParamMeta &row, const dev::RawValue &a, const dev::RawValue &b)
{
    if (dev::isText(a) || dev::isText(b)) {
        if (!dev::isText(a) || !dev::isText(b))
            return false;
        return trimmed(std::get<std::string>(a)) == trimmed(std::get<std::string>(b));
    }
    if (row.isFloat())
        return static_cast<float>(dev::rawNumber(a)) == static_cast<float>(dev::rawNumber(b));
    return dev::rawNumber(a) == dev::rawNumber(b);
}

Json moduleJson(const model::ModuleInfo &module)
{
    const auto &id = module.identification;
    return Json{
        {"address", module.address}, {"family", id.family},
        {"version", id.version},     {"mode", id.mode},
        {"exact", id.exact},         {"warning", id.exact ? Json(nullptr) : Json(id.warning.en)}};
}

std::string moduleText(const model::ModuleInfo &module, const char *noun)
{
    const auto &id = module.identification;
    std::string s = std::string(noun) + " " + std::to_string(module.address) + ": " + id.family;
    if (!id.version.empty())
        s += (id.version.front() >= '0' && id.version.front() <= '9' ? " V" : ", ") + id.version;
    if (!id.mode.empty())
        s += ", mode " + id.mode;
    return s;
}

std::string outcomeText(const model::Outcome &outcome, dev::Language lang)
{
    if (outcome.status == model::OutcomeStatus::DeviceException &&
        !outcome.reply.exceptionText.en.empty())
        return "refused by the device: " + outcome.reply.exceptionText.in(lang);
    if (!outcome.reason.isEmpty())
        return str(outcome.reason);
    return str(model::outcomeStatusText(outcome.status));
}

int exitCodeOf(const model::Outcome &outcome)
{
    return outcome.status == model::OutcomeStatus::LinkLost ? kExitConnection : kExitDeviceError;
}

Json writeItemJson(const model::WriteItem &item, dev::Language lang)
{
    const dev::ParamMeta &row = *item.row;
    const QString reason = model::writeReasonText(item, lang);
    return Json{{"name", row.name},
                {"value", optionalValue(row, item.value, lang)},
                {"before", optionalValue(row, item.before, lang)},
                {"status", model::writeStatusKey(item.status)},
                {"reason", reason.isEmpty() ? Json(nullptr) : Json(str(reason))},
                {"read_back", optionalValue(row, item.readBack, lang)}};
}

void printWriteItem(std::ostream &out, const model::WriteItem &item, dev::Language lang)
{
    const dev::ParamMeta &row = *item.row;
    out << std::left << std::setw(kNameWidth) << row.name << ' ';
    if (item.before)
        out << displayOf(row, *item.before, lang) << " -> ";
    out << displayOf(row, item.value, lang);
    if (item.status != model::WriteStatus::Pending) // a dry run lists pending rows
        out << "  " << model::writeStatusKey(item.status);
    if (const QString reason = model::writeReasonText(item, lang); !reason.isEmpty())
        out << " (" << str(reason) << ')';
    out << '\n';
}

int exitCodeOf(const std::vector<model::WriteItem> &items, bool linkLost)
{
    bool mismatch = false, refused = false, local = false, unfinished = false;
    for (const model::WriteItem &item : items) {
        mismatch |= item.status == model::WriteStatus::Mismatch;
        refused |= item.status == model::WriteStatus::Refused;
        local |= item.status == model::WriteStatus::RefusedLocally;
        unfinished |= item.status == model::WriteStatus::Uncertain ||
                      item.status == model::WriteStatus::NotSent ||
                      item.status == model::WriteStatus::Pending;
    }
    if (linkLost) // even a row written but not read back: the promise was "verified"
        return kExitConnection;
    if (mismatch)
        return kExitVerification;
    if (refused || unfinished)
        return kExitDeviceError;
    if (local)
        return kExitUsage;
    return kExitOk;
}

void printWarnings(std::ostream &err, int module, const std::vector<model::RowValue> &values,
                   dev::Language lang)
{
    for (const model::RowValue &v : values)
        if (v.warningCode != 0 && v.row)
            err << "valvetune-cli: warning: module " << module << ": " << v.row->name << ": "
                << v.warning.in(lang) << " (" << v.warningCode << ")\n";
}

std::string fixed(double v, int decimals)
{
    if (!std::isfinite(v))
        return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

Json numberOrNull(double v)
{
    return std::isfinite(v) ? Json(v) : Json(nullptr);
}

std::optional<double> parseDecimal(const QString &text, dev::Language lang)
{
    QLocale locale(lang == dev::Language::German ? QLocale::German : QLocale::C);
    locale.setNumberOptions(QLocale::RejectGroupSeparator);
    bool ok = false;
    const double v = locale.toDouble(text.trimmed(), &ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace vt::cli
