#include "identity_texts.h"

#include "dict/cooking.h"

#include <iterator>
#include <string_view>

namespace vt::model {
namespace {

// HART-7 manual §5.1: the texts a HART device carries for people, in the order PASO's
// "Fieldbus Settings" shows them (§3.4: tag; §6.4 delivery state of tag and long tag).
constexpr const char *kTextRows[] = {"hart_Tag", "hart_LongTag", "hart_Descriptor", "hart_Message"};
constexpr const char *kTextKeys[] = {"tag", "long_tag", "descriptor", "message"};
constexpr const char *kDateRows[] = {"hart_DateDay", "hart_DateMonth", "hart_DateYear"};

class Texts
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::IdentityTexts)
public:
    static QString date(double day, double month, double yearSince1900)
    {
        // HART-7 manual §5.1.11: "Date (day, month, year)", the year counted from 1900.
        return tr("%1-%2-%3")
            .arg(int(1900 + yearSince1900))
            .arg(int(month), 2, 10, QLatin1Char('0'))
            .arg(int(day), 2, 10, QLatin1Char('0'));
    }
    static QString dateLabel() { return tr("Date"); }
};

} // namespace

std::vector<const dev::ParamMeta *> identityTextRows(const dev::Dictionary &dictionary)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const char *name : kTextRows)
        if (const dev::ParamMeta *row = dictionary.find(name))
            rows.push_back(row);
    for (const char *name : kDateRows)
        if (const dev::ParamMeta *row = dictionary.find(name))
            rows.push_back(row);
    return rows;
}

std::vector<IdentityText>
identityTexts(const dev::Dictionary &dictionary,
              const std::function<std::optional<dev::RawValue>(const dev::ParamMeta *)> &valueOf,
              dev::Language lang)
{
    std::vector<IdentityText> out;
    for (std::size_t k = 0; k < std::size(kTextRows); ++k) {
        const char *name = kTextRows[k];
        const dev::ParamMeta *row = dictionary.find(name);
        if (!row)
            continue;
        const auto value = valueOf(row);
        out.push_back({kTextKeys[k], QString::fromStdString(row->label.in(lang)),
                       !value                ? QString()
                       : dev::isText(*value) ? QString::fromStdString(std::get<std::string>(*value))
                                             : QString::fromStdString(dev::formatValue(
                                                   *row, dev::rawNumber(*value), lang)),
                       value.has_value()});
        if (std::string_view(name) == "hart_Descriptor") {
            // The date sits beside the descriptor in command 13.
            std::optional<dev::RawValue> parts[3];
            bool all = true;
            for (int i = 0; i < 3; ++i) {
                const dev::ParamMeta *part = dictionary.find(kDateRows[i]);
                parts[i] = part ? valueOf(part) : std::nullopt;
                all = all && parts[i];
            }
            if (dictionary.find(kDateRows[0]))
                out.push_back(
                    {"date", Texts::dateLabel(),
                     all ? Texts::date(dev::rawNumber(*parts[0]), dev::rawNumber(*parts[1]),
                                       dev::rawNumber(*parts[2]))
                         : QString(),
                     all});
        }
    }
    return out;
}

} // namespace vt::model
