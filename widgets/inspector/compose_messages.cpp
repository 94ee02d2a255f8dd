#include "compose_messages.h"

#include "core/hex.h"
#include "inspect/logged_frame.h"
#include "model/text_language.h"

#include <QCoreApplication>
#include <QLocale>
#include <map>

namespace vt::ui {
QString composeRefusalText(const dev::inspect::ComposeError &error,
                           const std::function<QString(const QString &key)> &labelOf)
{
    // ComposeSpec members whose panel field has another key.
    static const std::map<std::string, QString> kPanelKey = {
        {"pollAddress", QStringLiteral("poll")},
        {"hartDeviceId", QStringLiteral("deviceId")},
        {"hartCommand", QStringLiteral("command")},
        {"hartData", QStringLiteral("data")}};
    const auto mapped = kPanelKey.find(error.field);
    const QString label = error.field.empty() ? QString()
                                              : labelOf(mapped != kPanelKey.end()
                                                            ? mapped->second
                                                            : QString::fromStdString(error.field));
    if (label.isEmpty())
        return QString::fromStdString(error.reason);
    const QLocale locale;
    return QCoreApplication::translate("vt::ui::ComposePanel", "%1 must be %2 to %3.")
        .arg(label, locale.toString(error.min), locale.toString(error.max));
}

std::optional<dev::inspect::ComposeKind> readKindFor(dev::LinkProtocol link)
{
    using dev::inspect::ComposeKind;
    switch (link) {
    case dev::LinkProtocol::NodeImage: return ComposeKind::GatewayRead;
    case dev::LinkProtocol::ModbusRtu:
    case dev::LinkProtocol::ModbusTcp: return ComposeKind::ModbusRead;
    case dev::LinkProtocol::Hart: return ComposeKind::HartParamRead;
    case dev::LinkProtocol::Canopen: return ComposeKind::SdoUpload;
    default: return std::nullopt; // the DSP-408 images carry no composed frame
    }
}

std::optional<dev::Description> decodeAnswer(const model::Outcome &outcome, dev::LinkProtocol link,
                                             const dev::inspect::ComposeSpec &request,
                                             const dev::Dictionary *dictionary)
{
    if (outcome.reply.frame.empty())
        return std::nullopt;
    dev::AnyOptions options;
    options.direction = dev::Direction::Response;
    options.family = request.family;
    options.dictionary = dictionary;
    const bool reads = request.kind == dev::inspect::ComposeKind::GatewayRead ||
                       request.kind == dev::inspect::ComposeKind::ModbusRead;
    const auto firstId = reads && request.id >= 0 && request.id <= 0xFFFF
                             ? std::optional<std::uint16_t>(static_cast<std::uint16_t>(request.id))
                             : std::nullopt;
    auto described = dev::inspect::describeLogged(link, outcome.reply.frame, options, firstId);
    if (!described)
        return std::nullopt;
    return *described;
}

std::function<QString()> answerText(const model::Outcome &outcome,
                                    const std::optional<dev::Description> &decoded)
{
    const QString hex = QString::fromStdString(dev::toHex(outcome.reply.frame));
    if (outcome.status == model::OutcomeStatus::Ok) {
        if (decoded && !decoded->summary.en.empty())
            return [summary = decoded->summary, hex] {
                return QCoreApplication::translate("vt::ui::ComposePanel", "Answered: %1 (%2)")
                    .arg(model::localText(summary), hex);
            };
        return [hex] {
            return QCoreApplication::translate("vt::ui::ComposePanel", "Answered: %1").arg(hex);
        };
    }
    return
        [status = outcome.status, reason = outcome.reason, device = outcome.reply.exceptionText] {
            const QString why = device.en.empty() ? reason : model::localText(device);
            return why.isEmpty() ? model::outcomeStatusText(status)
                                 : QCoreApplication::translate("vt::ui::ComposePanel", "%1: %2")
                                       .arg(model::outcomeStatusText(status), why);
        };
}

const dev::ParamMeta *rowWrittenBy(const dev::Dictionary *dictionary,
                                   const dev::inspect::ComposeSpec &spec)
{
    using dev::inspect::ComposeKind;
    if (!dictionary)
        return nullptr;
    for (const dev::ParamMeta &row : dictionary->params) {
        switch (spec.kind) {
        case ComposeKind::GatewayWrite:
        case ComposeKind::ModbusWrite:
            if (row.id && *row.id == spec.id)
                return &row;
            break;
        case ComposeKind::HartParamWrite:
        case ComposeKind::PkwWrite:
            if (row.ind && row.pnu && *row.ind == spec.ind && *row.pnu == spec.pnu &&
                (spec.kind == ComposeKind::PkwWrite || row.instance == spec.instance))
                return &row;
            break;
        case ComposeKind::SdoDownload:
            if (row.canopen && row.canopen->index == spec.index &&
                row.canopen->sub == spec.subindex)
                return &row;
            break;
        default: return nullptr;
        }
    }
    return nullptr;
}

} // namespace vt::ui
