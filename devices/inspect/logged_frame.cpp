#include "logged_frame.h"

#include "canopen/can_frame.h"
#include "canopen/sdo.h"
#include "core/hex.h"
#include "dict/cooking.h"
#include "hcs/describe.h"
#include "hcs/profiles.h"
#include "modbus/describe.h"

namespace vt::dev::inspect {

hcs::ParameterHooks parameterHooks(const Dictionary *dict)
{
    if (!dict)
        return {};
    hcs::ParameterHooks hooks;
    hooks.name = [dict](std::uint16_t id) -> std::optional<LocalText> {
        const ParamMeta *p = dict->findId(id);
        if (!p)
            return std::nullopt;
        return LocalText{p->name + " " + p->label.en, p->name + " " + p->label.de};
    };
    hooks.cook = [dict](std::uint16_t id, std::uint16_t raw) -> std::optional<LocalText> {
        const ParamMeta *p = dict->findId(id);
        if (!p || p->isString())
            return std::nullopt;
        // HCS words: signed unless the row's type says otherwise (as describeAny does).
        const double value = p->type == RawType::UInt16 ? raw : static_cast<std::int16_t>(raw);
        return LocalText{formatValue(*p, value, Language::English),
                         formatValue(*p, value, Language::German)};
    };
    return hooks;
}

Result<hcs::DescribeOptions, std::string> gatewayOptions(const AnyOptions &options)
{
    hcs::DescribeOptions node;
    if (!options.profile.empty()) {
        node.profile = hcs::profileByKey(options.profile);
        if (!node.profile)
            return std::string("unknown CMD 15 profile '" + options.profile + "'");
    }
    node.family = options.family;
    node.direction = options.direction;
    node.parameters = parameterHooks(options.dictionary);
    return node;
}

Description describeSocketCanImage(std::span<const std::uint8_t> image)
{
    const auto frame = canopen::fromSocketCan(image);
    if (!frame) {
        Description d;
        d.protocol = "canopen-sdo";
        d.error = frame.error();
        d.summary = describeError(*d.error);
        return d;
    }
    Description inner = canopen::describeSdo(*frame);
    Description d;
    d.protocol = inner.protocol;
    d.summary = inner.summary;
    // Linux <linux/can.h> struct can_frame: can_id (host order), len, 3 reserved, data[8].
    const std::string id = frame->extended
                               ? "0x" + toHex(std::span<const std::uint8_t>(image.first(4)), '\0')
                               : hexWord(static_cast<std::uint16_t>(frame->id));
    LocalText idText{"CAN identifier (SocketCAN can_id, host byte order)",
                     "CAN-Kennung (SocketCAN can_id, Host-Byte-Reihenfolge)"};
    for (const FieldSpan &f : inner.fields)
        if (f.key == "can.id")
            idText = f.text;
    d.fields.push_back({"can.id", 0, 4, 0, id, idText});
    d.fields.push_back(
        {"can.len", 4, 1, 0, std::to_string(frame->dlc), {"data length", "Datenlänge"}});
    d.fields.push_back({"can.reserved",
                        5,
                        3,
                        0,
                        toHex(image.subspan(5, 3)),
                        {"padding / reserved", "Füllbytes / reserviert"}});
    constexpr std::size_t kData = 8;
    for (FieldSpan f : inner.fields) {
        if (f.key == "can.id")
            continue;
        f.offset += kData;
        d.fields.push_back(std::move(f));
    }
    if (inner.error) {
        d.error = inner.error;
        d.error->offset += kData;
    }
    return d;
}

Result<Description, std::string> describeLogged(LinkProtocol link,
                                                std::span<const std::uint8_t> bytes,
                                                AnyOptions options,
                                                std::optional<std::uint16_t> firstId)
{
    const FrameFormat format = frameFormatOf(link);
    if (format == FrameFormat::Canopen && bytes.size() == canopen::kSocketCanFrameSize)
        return describeSocketCanImage(bytes);
    options.protocol = format;
    if (firstId && (format == FrameFormat::ModbusRtu || format == FrameFormat::ModbusTcp)) {
        modbus::DescribeOptions o;
        o.direction = options.direction;
        o.family = options.family;
        o.requestStart = firstId;
        o.parameters = parameterHooks(options.dictionary);
        return format == FrameFormat::ModbusRtu ? modbus::describeRtu(bytes, o)
                                                : modbus::describeTcp(bytes, o);
    }
    if (link != LinkProtocol::NodeImage)
        return describeAny(bytes, options);
    // describeAny has no padding option: ask the gateway codec directly, with the same hooks.
    auto node = gatewayOptions(options);
    if (!node.ok())
        return node.error();
    node->allowPadding = true;
    node->firstId = firstId;
    return hcs::describe(bytes, *node);
}

} // namespace vt::dev::inspect
