#include "language_text.h"

#include "dict/dictionary.h"
#include "model/text_language.h"

#include <QCoreApplication>
#include <QLocale>

namespace vt::ui {

QString familyText(const dev::Dictionary &dictionary)
{
    return QCoreApplication::translate("vt::ui::DictionaryTexts", "%1 (%2)")
        .arg(model::localText(dictionary.title), QString::fromStdString(dictionary.family));
}

QString modeText(const dev::Dictionary &dictionary, const std::string &mode)
{
    const QString number = QString::fromStdString(mode);
    bool numeric = false;
    const int raw = number.toInt(&numeric);
    const dev::ParamMeta *e00 =
        dictionary.protocol == dev::DeviceProtocol::Hcs ? dictionary.find("E00") : nullptr;
    const dev::EnumLabel *label = numeric && e00 ? e00->findEnum(raw) : nullptr;
    if (!label)
        return number;
    return QCoreApplication::translate("vt::ui::DictionaryTexts", "%1 — %2")
        .arg(QLocale().toString(raw), model::localText(label->text));
}

} // namespace vt::ui
