#include "dictionary_validate.h"

#include <cmath>
#include <set>
#include <tuple>

namespace vt::dev {
namespace {

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

void checkText(std::vector<DictionaryError> &out, const std::string &row, const char *what,
               const LocalText &t, bool required)
{
    if (!required && t.en.empty() && t.de.empty())
        return;
    if (t.en.empty())
        out.push_back({{}, row, std::string(what) + " has no English text"});
    if (t.de.empty())
        out.push_back({{}, row, std::string(what) + " has no German text"});
}

// A row's kind must agree with what the manual says about the same row elsewhere: its access,
// its persistence column and its PZD number (docs/DICTIONARY.md "Row kinds").
void checkRowKind(std::vector<DictionaryError> &out, const ParamMeta &p)
{
    auto fail = [&](std::string message) { out.push_back({{}, p.name, std::move(message)}); };
    const std::string kind = key(p.kind);
    if (p.kind == RowKind::Live && p.writable())
        fail("a live value is read only, but access is " + std::string(accessKey(p.access)));
    if (p.kind == RowKind::Process && !p.writable())
        fail("a process value is written at run time; a read-only run-time value is live");
    if (p.movesActuator && !p.writable())
        fail("moves_actuator on a row that cannot be written (access " +
             std::string(accessKey(p.access)) + ")");
    if (p.kind != RowKind::Setting && p.persistence == Persistence::Eeprom)
        fail("a " + kind + " value is kept in EEPROM; a value the device keeps is a setting");
    if (p.kind == RowKind::Setting && p.persistence == Persistence::Volatile && p.writable())
        fail("a writable volatile value is lost at power down: a process value, not a setting");
    if (p.kind == RowKind::Setting && p.access == Access::Write)
        fail("a write-only row is a command, not a setting: a file cannot hold what cannot be "
             "read back");
    // ED1/SD1 manual §4.4: "All parameters with an entry in the column PZD-number can be
    // transmitted as process data (PZD)".
    if (p.kind == RowKind::Setting && p.pzd)
        fail("a row with a PZD number is process data, not a setting");
}

} // namespace

std::vector<DictionaryError> validateDictionary(const Dictionary &dict)
{
    std::vector<DictionaryError> out;
    auto fail = [&](const std::string &row, std::string message) {
        out.push_back({{}, row, std::move(message)});
    };

    if (!dict.title.complete())
        fail({}, "\"title\" needs en and de");
    std::set<std::string> names;
    std::set<int> ids;
    std::set<std::tuple<int, int, int>> addresses;
    for (const ParamMeta &p : dict.params) {
        const std::string &row = p.name;
        if (!names.insert(p.name).second)
            fail(row, "duplicate name");
        if (dict.protocol == DeviceProtocol::Hcs) {
            if (!p.id)
                fail(row, "HCS row without \"id\"");
            else if (!ids.insert(*p.id).second)
                fail(row, "duplicate id " + std::to_string(*p.id));
        } else {
            if (!p.ind || !p.pnu)
                fail(row, "Wandfluh row without \"ind\"/\"pnu\"");
            else if (!addresses.insert({*p.ind, *p.pnu, p.instance}).second)
                fail(row, "duplicate ind/pnu/instance");
        }
        if (p.block.empty())
            fail(row, "missing \"block\"");
        checkRowKind(out, p);
        checkText(out, row, "label", p.label, true);
        checkText(out, row, "description", p.description, false);

        if (p.isString()) {
            if (p.length <= 0)
                fail(row, "string without a positive \"length\"");
            continue;
        }
        if (!(p.min <= p.max))
            fail(row, "min " + num(p.min) + " > max " + num(p.max));
        if (p.min < typeMin(p.type) || p.max > typeMax(p.type))
            fail(row,
                 "range " + num(p.min) + ".." + num(p.max) + " does not fit " + rawTypeKey(p.type));
        if (!p.isFloat() && (p.min != std::floor(p.min) || p.max != std::floor(p.max)))
            fail(row, "integer type with a fractional limit");
        if (!(p.step > 0))
            fail(row, "step must be positive");
        if (p.defaultValue && (*p.defaultValue < p.min || *p.defaultValue > p.max))
            fail(row,
                 "default " + num(*p.defaultValue) + " outside " + num(p.min) + ".." + num(p.max));
        std::set<std::int64_t> enumValues;
        for (const EnumLabel &e : p.enums) {
            const auto v = static_cast<double>(e.value);
            if (v < p.min || v > p.max)
                fail(row, "enum value " + std::to_string(e.value) + " outside the range");
            if (!enumValues.insert(e.value).second)
                fail(row, "duplicate enum value " + std::to_string(e.value));
            checkText(out, row, ("enum " + std::to_string(e.value)).c_str(), e.text, true);
        }
        std::set<int> bitNumbers;
        for (const BitLabel &b : p.bits) {
            if (b.bit < 0 || b.bit > 31)
                fail(row, "bit number " + std::to_string(b.bit) + " outside 0..31");
            if (!bitNumbers.insert(b.bit).second)
                fail(row, "duplicate bit " + std::to_string(b.bit));
            checkText(out, row, ("bit " + std::to_string(b.bit)).c_str(), b.text, true);
        }
        for (const std::string *ref : {&p.minParam, &p.maxParam})
            if (!ref->empty() && !dict.find(*ref))
                fail(row, "limit refers to unknown parameter '" + *ref + "'");
    }
    return out;
}

} // namespace vt::dev
