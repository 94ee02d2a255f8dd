// valvetune-cli encode: builds gateway telegrams (CMD 3/6/15) and Modbus RTU frames from named
// arguments, for PLC programmers who need the exact bytes.
//   encode gateway read   --tadr T --sadr S --id ID [--count N]
//   encode gateway write  --tadr T --sadr S --id ID --value V
//   encode gateway cyclic --family opat|dma --tadr T --module CTRL,VALUE1,VALUE2 [--module …]
//   encode modbus-rtu read  --unit U --id ID [--count N]
//   encode modbus-rtu write --unit U --id ID --value V
#include "commands.h"
#include "core/hex.h"
#include "hcs/cmd15.h"
#include "hcs/node_rules.h"
#include "hcs/telegram.h"
#include "inspect/describe_any.h"
#include "modbus/rtu.h"

#include <nlohmann/json.hpp>

namespace vt::cli {
namespace {

using Json = nlohmann::ordered_json;

const char kUsage[] =
    "usage: valvetune-cli encode gateway read   --tadr T --sadr S --id ID [--count N]\n"
    "       valvetune-cli encode gateway write  --tadr T --sadr S --id ID --value V\n"
    "       valvetune-cli encode gateway cyclic --family opat|dma --tadr T --module "
    "CTRL,VALUE1,VALUE2 [--module ...]\n"
    "       valvetune-cli encode modbus-rtu read  --unit U --id ID [--count N]\n"
    "       valvetune-cli encode modbus-rtu write --unit U --id ID --value V\n"
    "Numbers in decimal or 0x hex; values are 16-bit words (-32768..65535).";

struct Args
{
    QStringList rest;
    Context &ctx;
    std::string problem;

    // Required or optional integer option with its range; records the first problem.
    std::optional<long long> number(const char *name, long long min, long long max,
                                    std::optional<long long> fallback = {})
    {
        bool missing = false;
        const auto text = takeOption(rest, name, &missing);
        if (!text) {
            if (!missing && fallback)
                return fallback;
            if (problem.empty())
                problem = std::string(name) + " is required";
            return std::nullopt;
        }
        const auto v = parseInteger(*text, min, max);
        if (!v && problem.empty())
            problem = std::string(name) + " takes a number from " + std::to_string(min) + " to " +
                      std::to_string(max) + ", not '" + text->toStdString() + "'";
        return v;
    }
};

int printFrame(Context &ctx, dev::FrameFormat format, const dev::Bytes &bytes)
{
    if (ctx.json) {
        Json list = Json::array();
        for (auto b : bytes)
            list.push_back(b);
        ctx.out << Json{{"protocol", dev::key(format)}, {"hex", dev::toHex(bytes)}, {"bytes", list}}
                       .dump()
                << '\n';
    } else {
        ctx.out << dev::toHex(bytes) << '\n';
    }
    return kExitOk;
}

} // namespace

int runEncode(const QStringList &argsIn, Context &ctx)
{
    QStringList rest = argsIn;
    if (takeFlag(rest, "--help")) {
        ctx.out << kUsage << '\n';
        return kExitOk;
    }
    if (rest.size() < 2)
        return ctx.fail(kExitUsage, kUsage);
    const auto protocol = dev::fromKey<dev::FrameFormat>(rest.takeFirst().toStdString());
    const QString kind = rest.takeFirst();
    Args a{rest, ctx, {}};
    auto finish = [&](auto build) -> int {
        if (!a.problem.empty())
            return ctx.fail(kExitUsage, a.problem);
        if (!a.rest.isEmpty())
            return ctx.fail(kExitUsage,
                            "unexpected argument '" + a.rest.first().toStdString() + "'");
        return build();
    };

    if (protocol == dev::FrameFormat::Gateway && (kind == "read" || kind == "write")) {
        const auto tadr = a.number("--tadr", 0, 255);
        const auto sadr = a.number("--sadr", 0, 255);
        const auto id = a.number("--id", 0, 0xFFFF);
        if (kind == "read") {
            const auto count = a.number("--count", 1, dev::hcs::kMaxReadCount, 1);
            return finish([&] {
                return printFrame(
                    ctx, dev::FrameFormat::Gateway,
                    dev::hcs::encode(dev::hcs::ReadRequest{
                        static_cast<std::uint8_t>(*tadr), static_cast<std::uint8_t>(*sadr),
                        static_cast<std::uint16_t>(*id), static_cast<std::uint16_t>(*count)}));
            });
        }
        const auto value = a.number("--value", -32768, 65535);
        return finish([&] {
            return printFrame(
                ctx, dev::FrameFormat::Gateway,
                dev::hcs::encode(dev::hcs::WriteRequest{
                    static_cast<std::uint8_t>(*tadr), static_cast<std::uint8_t>(*sadr),
                    static_cast<std::uint16_t>(*id), static_cast<std::uint16_t>(*value)}));
        });
    }
    if (protocol == dev::FrameFormat::Gateway && kind == "cyclic") {
        bool missing = false;
        const auto familyText = takeOption(a.rest, "--family", &missing);
        const auto family =
            familyText ? dev::hcs::familyFromName(familyText->toStdString()) : std::nullopt;
        if (!family)
            return ctx.fail(kExitUsage,
                            "--family opat|dma is required for cyclic (CMD 15) telegrams");
        const auto tadr = a.number("--tadr", 0, 255);
        dev::hcs::CyclicRequest request;
        while (const auto module = takeOption(a.rest, "--module", &missing)) {
            const QStringList parts = module->split(',');
            const auto control = parts.size() == 3 ? parseInteger(parts[0], 0, 255) : std::nullopt;
            const auto v1 =
                parts.size() == 3 ? parseInteger(parts[1], -32768, 32767) : std::nullopt;
            const auto v2 =
                parts.size() == 3 ? parseInteger(parts[2], -32768, 32767) : std::nullopt;
            if (!control || !v1 || !v2)
                return ctx.fail(
                    kExitUsage,
                    "--module takes CTRL,VALUE1,VALUE2 (0..255, two -32768..32767), not '" +
                        module->toStdString() + "'");
            request.modules.push_back({static_cast<std::uint8_t>(*control),
                                       static_cast<std::int16_t>(*v1),
                                       static_cast<std::int16_t>(*v2)});
        }
        if (request.modules.empty())
            return ctx.fail(kExitUsage, "at least one --module is required");
        return finish([&] {
            request.tadr = static_cast<std::uint8_t>(*tadr);
            const auto bytes = dev::hcs::encode(request, *family);
            if (!bytes.ok())
                return ctx.fail(kExitUsage,
                                "a " + std::string(familyText->toStdString()) +
                                    " node cannot carry " + std::to_string(request.modules.size()) +
                                    " modules in CMD 15 (" + bytes.error().detail + ")");
            return printFrame(ctx, dev::FrameFormat::Gateway, *bytes);
        });
    }
    if (protocol == dev::FrameFormat::ModbusRtu && (kind == "read" || kind == "write")) {
        const auto unit = a.number("--unit", 0, 247);
        const auto id = a.number("--id", 0, 0xFFFF);
        dev::modbus::RtuRequest request;
        if (kind == "read") {
            // HCS rule: at most 8 parameters per request (OPAT manual §2.1).
            const auto count = a.number("--count", 1, dev::hcs::kMaxReadCount, 1);
            if (a.problem.empty())
                request.pdu = dev::modbus::ReadRequest{static_cast<std::uint16_t>(*id),
                                                       static_cast<std::uint16_t>(*count)};
        } else {
            const auto value = a.number("--value", -32768, 65535);
            if (a.problem.empty())
                request.pdu = dev::modbus::WriteRequest{static_cast<std::uint16_t>(*id),
                                                        static_cast<std::uint16_t>(*value)};
        }
        return finish([&] {
            request.unit = static_cast<std::uint8_t>(*unit);
            const auto bytes = dev::modbus::encodeRtu(request);
            if (!bytes.ok())
                return ctx.fail(kExitUsage, bytes.error().detail);
            return printFrame(ctx, dev::FrameFormat::ModbusRtu, *bytes);
        });
    }
    return ctx.fail(kExitUsage, kUsage);
}

} // namespace vt::cli
