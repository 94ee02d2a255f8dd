#include "dsp408/gateway.h"

#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "modbus/register_image.h"

#include <string>
#include <variant>

namespace vt::dev::dsp408 {
namespace {

constexpr std::size_t kMbap = modbus::kMbapSize;

void addChildren(Description &into, const Description &part, std::size_t offset)
{
    for (FieldSpan f : part.fields) {
        f.offset += offset;
        ++f.depth;
        into.fields.push_back(std::move(f));
    }
}

void fail(Description &d, DecodeError error, std::size_t offset)
{
    error.offset += offset;
    d.error = error;
    d.summary = describeError(error);
}

LocalText joined(const LocalText &head, const LocalText &tail)
{
    return {head.en + ": " + tail.en, head.de + ": " + tail.de};
}

// The image part `registers` (written or read) as the PKW / PZD codecs describe it.
LocalText describeImagePart(Description &d, std::span<const std::uint16_t> registers,
                            std::size_t offset, const Options &options, RegisterByteOrder order)
{
    const Bytes bytes = fromRegisters(registers, order);
    const bool request = options.direction == Direction::Request;
    if (registers.size() == kImageRegisters) {
        const Description image = describeTelegram(bytes, options);
        addChildren(d, image, offset);
        return image.summary;
    }
    if (registers.size() == kPkwRegisters) {
        const Description pkw = describePkw(bytes, options);
        addChildren(d, pkw, offset);
        return pkw.summary;
    }
    if (request && registers.size() == 1) {
        const std::string w = std::to_string(bytes[0] << 8 | bytes[1]);
        d.fields.push_back({"pzd.control_word",
                            offset,
                            2,
                            1,
                            w,
                            {"control word (db_ControlWord)", "Steuerwort (db_ControlWord)"}});
        return {"control word " + w, "Steuerwort " + w};
    }
    if (request && registers.size() == 2) {
        const bool highFirst = options.pzdWordOrder == WordOrder::HighWordFirst;
        const std::uint32_t first = static_cast<std::uint32_t>(bytes[0] << 8 | bytes[1]);
        const std::uint32_t second = static_cast<std::uint32_t>(bytes[2] << 8 | bytes[3]);
        const std::uint32_t high = highFirst ? first : second;
        const std::uint32_t low = highFirst ? second : first;
        const std::string v = std::to_string(static_cast<std::int32_t>(high << 16 | low));
        d.fields.push_back({"pzd.setpoint",
                            offset,
                            4,
                            1,
                            v,
                            {"set value (dpc_SetpointVal)", "Sollwert (dpc_SetpointVal)"}});
        return {"set value " + v, "Sollwert " + v};
    }
    return {std::to_string(registers.size()) + " registers",
            std::to_string(registers.size()) + " Register"};
}

} // namespace

std::vector<std::uint16_t> toRegisters(std::span<const std::uint8_t> image, RegisterByteOrder order)
{
    std::vector<std::uint16_t> out;
    out.reserve((image.size() + 1) / 2);
    for (std::size_t i = 0; i < image.size(); i += 2) {
        const std::uint16_t first = image[i];
        const std::uint16_t second = i + 1 < image.size() ? image[i + 1] : 0;
        out.push_back(order == RegisterByteOrder::FirstByteHigh
                          ? static_cast<std::uint16_t>(first << 8 | second)
                          : static_cast<std::uint16_t>(second << 8 | first));
    }
    return out;
}

Bytes fromRegisters(std::span<const std::uint16_t> registers, RegisterByteOrder order)
{
    Bytes out;
    out.reserve(2 * registers.size());
    for (std::uint16_t r : registers) {
        const auto high = static_cast<std::uint8_t>(r >> 8);
        const auto low = static_cast<std::uint8_t>(r);
        out.push_back(order == RegisterByteOrder::FirstByteHigh ? high : low);
        out.push_back(order == RegisterByteOrder::FirstByteHigh ? low : high);
    }
    return out;
}

Description describeGatewayAdu(std::span<const std::uint8_t> adu, const Options &options,
                               RegisterByteOrder order)
{
    Description d;
    d.protocol = "dsp408-gateway";
    auto header = modbus::decodeMbap(adu);
    if (!header.ok()) {
        fail(d, header.error(), 0);
        return d;
    }
    const std::size_t size = header->aduSize();
    d.fields.push_back({"mbap.transaction",
                        0,
                        2,
                        0,
                        std::to_string(header->transaction),
                        {"transaction identifier", "Transaktionskennung"}});
    d.fields.push_back({"mbap.length",
                        4,
                        2,
                        0,
                        std::to_string(header->length),
                        {"bytes that follow", "folgende Bytes"}});
    d.fields.push_back({"mbap.unit",
                        6,
                        1,
                        0,
                        std::to_string(header->unit),
                        {"unit identifier (gateway)", "Unit-Kennung (Gateway)"}});
    if (adu.size() != size) {
        fail(d,
             DecodeError{adu.size() < size ? DecodeErrc::Truncated : DecodeErrc::TooLong,
                         std::min(adu.size(), size), 0,
                         "MBAP length announces " + std::to_string(size) + " bytes"},
             0);
        return d;
    }
    const auto pdu = adu.subspan(kMbap);
    const std::size_t data = kMbap + 6; // FC 16 request: fc, start, count, byte count
    LocalText summary;
    if (options.direction == Direction::Request) {
        auto request = modbus::decodeRegisterRequest(pdu);
        if (!request.ok()) {
            fail(d, request.error(), kMbap);
            return d;
        }
        if (const auto *read = std::get_if<modbus::RegisterRead>(&*request)) {
            d.fields.push_back({"pdu.function",
                                kMbap,
                                1,
                                0,
                                std::to_string(read->function),
                                {"read the input image", "Eingangsabbild lesen"}});
            d.fields.push_back({"pdu.start",
                                kMbap + 1,
                                2,
                                0,
                                std::to_string(read->start),
                                {"first register", "erstes Register"}});
            d.fields.push_back({"pdu.count",
                                kMbap + 3,
                                2,
                                0,
                                std::to_string(read->count),
                                {"registers", "Register"}});
            summary = {"FC " + std::to_string(read->function) + " read " +
                           std::to_string(read->count) + " registers from " +
                           std::to_string(read->start),
                       "FC " + std::to_string(read->function) + " " + std::to_string(read->count) +
                           " Register ab " + std::to_string(read->start) + " lesen"};
        } else {
            const auto &write = std::get<modbus::RegisterWrite>(*request);
            d.fields.push_back({"pdu.function",
                                kMbap,
                                1,
                                0,
                                "16",
                                {"write the output image", "Ausgangsabbild schreiben"}});
            d.fields.push_back({"pdu.start",
                                kMbap + 1,
                                2,
                                0,
                                std::to_string(write.start),
                                {"first register", "erstes Register"}});
            d.fields.push_back({"pdu.count",
                                kMbap + 3,
                                2,
                                0,
                                std::to_string(write.values.size()),
                                {"registers", "Register"}});
            const LocalText part = describeImagePart(d, write.values, data, options, order);
            summary = joined({"FC 16 at " + std::to_string(write.start),
                              "FC 16 ab " + std::to_string(write.start)},
                             part);
        }
    } else {
        auto response = modbus::decodeRegisterResponse(pdu);
        if (!response.ok()) {
            fail(d, response.error(), kMbap);
            return d;
        }
        if (const auto *read = std::get_if<modbus::RegisterReadAnswer>(&*response)) {
            d.fields.push_back({"pdu.function",
                                kMbap,
                                1,
                                0,
                                std::to_string(read->function),
                                {"input image", "Eingangsabbild"}});
            d.fields.push_back({"pdu.byte_count",
                                kMbap + 1,
                                1,
                                0,
                                std::to_string(2 * read->registers.size()),
                                {"byte count", "Byteanzahl"}});
            summary = describeImagePart(d, read->registers, kMbap + 2, options, order);
        } else if (const auto *written = std::get_if<modbus::RegisterWriteAnswer>(&*response)) {
            d.fields.push_back({"pdu.function",
                                kMbap,
                                1,
                                0,
                                "16",
                                {"output image written", "Ausgangsabbild geschrieben"}});
            d.fields.push_back({"pdu.start",
                                kMbap + 1,
                                2,
                                0,
                                std::to_string(written->start),
                                {"first register", "erstes Register"}});
            d.fields.push_back({"pdu.count",
                                kMbap + 3,
                                2,
                                0,
                                std::to_string(written->count),
                                {"registers", "Register"}});
            summary = {"FC 16 written: " + std::to_string(written->count) + " registers",
                       "FC 16 geschrieben: " + std::to_string(written->count) + " Register"};
        } else {
            const auto &e = std::get<modbus::RegisterException>(*response);
            d.fields.push_back({"pdu.exception",
                                kMbap + 1,
                                1,
                                0,
                                std::to_string(e.code),
                                {"Modbus exception code", "Modbus-Ausnahmecode"}});
            summary = {"FC " + std::to_string(e.function) + " exception " + std::to_string(e.code),
                       "FC " + std::to_string(e.function) + " Ausnahme " + std::to_string(e.code)};
        }
    }
    d.summary = summary;
    return d;
}

} // namespace vt::dev::dsp408
