#include "hart/describe.h"

#include "core/byte_reader.h"
#include "core/hex.h"
#include "hart/device_specific.h"
#include "hart/frame.h"
#include "hart/texts.h"
#include "hart/universal.h"

#include <string>

namespace vt::dev::hart {
namespace {

LocalText frameTypeText(std::uint8_t type)
{
    switch (type) {
    case 1:
        return {"BACK: burst frame, field device to master",
                "BACK: Burst-Telegramm, Feldgerät an Master"};
    case 2: return {"STX: master to field device", "STX: Master an Feldgerät"};
    case 6: return {"ACK: field device to master", "ACK: Feldgerät an Master"};
    default: return {"invalid frame type", "ungültiger Telegrammtyp"};
    }
}

std::string addressValue(const Address &a)
{
    if (!a.isLong)
        return "poll " + std::to_string(a.pollAddress);
    return hexWord(a.expandedDeviceType) + "/" + std::to_string(a.deviceId);
}

void describeAddress(const Address &a, std::size_t at, std::size_t size,
                     std::vector<FieldSpan> &out)
{
    out.push_back({"hart.address", at, size, 0, addressValue(a),
                   a.isLong ? LocalText{"long address", "Langadresse"}
                            : LocalText{"short address", "Kurzadresse"}});
    out.push_back({"hart.address.master", at, 1, 1, a.primaryMaster ? "1" : "0",
                   a.primaryMaster ? LocalText{"primary master", "primärer Master"}
                                   : LocalText{"secondary master", "sekundärer Master"}});
    out.push_back({"hart.address.burst", at, 1, 1, a.burst ? "1" : "0",
                   a.burst ? LocalText{"field device in burst mode", "Feldgerät im Burst-Modus"}
                           : LocalText{"not in burst mode", "nicht im Burst-Modus"}});
    if (!a.isLong) {
        out.push_back({"hart.address.poll",
                       at,
                       1,
                       1,
                       std::to_string(a.pollAddress),
                       {"polling address", "Polling-Adresse"}});
        return;
    }
    out.push_back({"hart.address.device_type",
                   at,
                   2,
                   1,
                   hexWord(a.expandedDeviceType),
                   {"expanded device type (bits 37..24)", "erweiterter Gerätetyp (Bits 37..24)"}});
    out.push_back({"hart.address.device_id",
                   at + 2,
                   3,
                   1,
                   std::to_string(a.deviceId),
                   {"device id (bits 23..0)", "Gerätekennung (Bits 23..0)"}});
}

void describeStatus(std::uint8_t rc, std::uint8_t status, std::size_t at,
                    std::vector<FieldSpan> &out)
{
    if (rc & 0x80) {
        out.push_back({"hart.response_code",
                       at,
                       1,
                       0,
                       hexByte(rc),
                       {"communication error", "Kommunikationsfehler"}});
        for (int bit = 6; bit >= 0; --bit)
            if (((static_cast<unsigned>(rc) >> static_cast<unsigned>(bit)) & 1u) != 0)
                out.push_back({"hart.comm_error.bit" + std::to_string(bit), at, 1, 1, "1",
                               commErrorBitText(bit)});
    } else {
        out.push_back({"hart.response_code", at, 1, 0, std::to_string(rc), responseCodeText(rc)});
    }
    out.push_back({"hart.device_status", at + 1, 1, 0, hexByte(status),
                   status == 0 ? LocalText{"field device status: OK", "Feldgerätestatus: OK"}
                               : LocalText{"field device status", "Feldgerätestatus"}});
    for (int bit = 7; bit >= 0; --bit)
        if (((static_cast<unsigned>(status) >> static_cast<unsigned>(bit)) & 1u) != 0)
            out.push_back({"hart.device_status.bit" + std::to_string(bit), at + 1, 1, 1, "1",
                           deviceStatusBitText(bit)});
}

std::optional<DecodeError> describePayload(std::uint8_t command, bool response,
                                           std::span<const std::uint8_t> data, std::size_t at,
                                           std::vector<FieldSpan> &out)
{
    if (isParameterCommand(command))
        return describeParamAccess(command, response, data, at, 1, out);
    if (isUniversal(command))
        return describeUniversal(command, response, data, at, 1, out);
    return std::nullopt;
}

LocalText summaryOf(const Frame &f)
{
    const LocalText cmd = commandText(f.command);
    const std::string head = std::string(f.type == FrameType::Stx   ? "STX"
                                         : f.type == FrameType::Ack ? "ACK"
                                                                    : "BACK") +
                             " " + addressValue(f.address) + " cmd " + std::to_string(f.command) +
                             " ";
    LocalText s{head + cmd.en, head + cmd.de};
    if (f.isResponse()) {
        const LocalText rc = (f.responseCode & 0x80)
                                 ? LocalText{"communication error", "Kommunikationsfehler"}
                                 : responseCodeText(f.responseCode);
        s.en += ": " + rc.en;
        s.de += ": " + rc.de;
    }
    return s;
}

} // namespace

Description describeFrame(std::span<const std::uint8_t> bytes, const DescribeOptions &options)
{
    Description d;
    d.protocol = "hart";
    auto decoded = decodeFrame(bytes);
    if (!decoded.ok())
        d.error = decoded.error();

    std::size_t preambles = 0;
    for (std::uint8_t b : bytes) {
        if (b != kPreamble)
            break;
        ++preambles;
    }
    if (preambles > 0)
        d.fields.push_back({"hart.preambles",
                            0,
                            preambles,
                            0,
                            std::to_string(preambles),
                            {"preambles (0xFF)", "Präambeln (0xFF)"}});
    ByteReader r(bytes);
    r.skip(preambles);
    const std::size_t start = r.offset();
    const std::uint8_t delimiter = r.u8();
    if (r.failed() || !isValidDelimiter(delimiter)) {
        if (!r.failed())
            d.fields.push_back({"hart.delimiter", start, 1, 0, hexByte(delimiter),
                                frameTypeText(delimiter & 0x07)});
        d.summary = d.error ? describeError(*d.error) : LocalText{};
        return d;
    }
    const bool isLong = (delimiter & 0x80) != 0;
    const auto type = static_cast<std::uint8_t>(delimiter & 0x07);
    const bool response = type != static_cast<std::uint8_t>(FrameType::Stx);
    d.fields.push_back({"hart.delimiter",
                        start,
                        1,
                        0,
                        hexByte(delimiter),
                        {"delimiter (start byte)", "Startzeichen (SD)"}});
    d.fields.push_back(
        {"hart.delimiter.frame_type", start, 1, 1, std::to_string(type), frameTypeText(type)});
    d.fields.push_back(
        {"hart.delimiter.address_type", start, 1, 1, isLong ? "1" : "0",
         isLong ? LocalText{"long frame (5-byte address)", "Langrahmen (5-Byte-Adresse)"}
                : LocalText{"short frame (1-byte address)", "Kurzrahmen (1-Byte-Adresse)"}});
    const std::size_t expansion = (delimiter >> 5) & 0x03;
    if (expansion > 0)
        d.fields.push_back({"hart.delimiter.expansion",
                            start,
                            1,
                            1,
                            std::to_string(expansion),
                            {"expansion bytes", "Erweiterungsbytes"}});
    if (((delimiter >> 3) & 0x03) != 0)
        d.fields.push_back({"hart.delimiter.physical_layer",
                            start,
                            1,
                            1,
                            std::to_string((delimiter >> 3) & 0x03),
                            {"physical layer type", "Typ der physikalischen Schicht"}});

    // The fixed header as far as it is present; decodeFrame has the verdict.
    const std::size_t addressAt = r.offset();
    const std::size_t addressSize = isLong ? 5 : 1;
    r.skip(addressSize);
    if (!r.failed())
        describeAddress(decodeAddress(bytes.subspan(addressAt, addressSize), isLong), addressAt,
                        addressSize, d.fields);
    const std::size_t expansionAt = r.offset();
    const auto expansionBytes = r.bytes(expansion);
    if (expansion > 0 && !r.failed())
        d.fields.push_back({"hart.expansion",
                            expansionAt,
                            expansion,
                            0,
                            toHex(expansionBytes),
                            {"expansion bytes", "Erweiterungsbytes"}});
    const std::size_t commandAt = r.offset();
    const std::uint8_t command = r.u8();
    if (!r.failed())
        d.fields.push_back(
            {"hart.command", commandAt, 1, 0, std::to_string(command), commandText(command)});
    const std::size_t countAt = r.offset();
    const std::uint8_t count = r.u8();
    if (!r.failed())
        d.fields.push_back({"hart.byte_count",
                            countAt,
                            1,
                            0,
                            std::to_string(count),
                            {"byte count (status + data)", "Byteanzahl (Status + Daten)"}});
    std::uint8_t rc = 0;
    std::size_t dataBytes = count;
    if (response && count >= 2) {
        const std::size_t statusAt = r.offset();
        rc = r.u8();
        const std::uint8_t status = r.u8();
        if (!r.failed())
            describeStatus(rc, status, statusAt, d.fields);
        dataBytes -= 2;
    }
    const std::size_t dataAt = r.offset();
    const auto data = r.bytes(dataBytes);
    if (r.failed()) {
        d.summary = d.error ? describeError(*d.error) : LocalText{};
        return d;
    }
    if (!data.empty())
        d.fields.push_back({"hart.data", dataAt, data.size(), 0, toHex(data), {"data", "Daten"}});
    const bool errorResponse = response && isErrorResponse(rc);
    if (options.payload && (!data.empty() || !errorResponse)) {
        auto payloadError = describePayload(command, response, data, dataAt, d.fields);
        // An error response may legitimately carry less than the command's layout.
        if (payloadError && !d.error && !errorResponse)
            d.error = payloadError;
    }
    const std::size_t checksumAt = r.offset();
    const std::uint8_t sum = r.u8();
    if (!r.failed()) {
        const std::uint8_t expected = checksum(bytes.subspan(start, checksumAt - start));
        d.fields.push_back({"hart.checksum", checksumAt, 1, 0, hexByte(sum),
                            sum == expected
                                ? LocalText{"checksum (XOR), correct", "Prüfsumme (XOR), korrekt"}
                                : LocalText{"checksum (XOR), expected " + hexByte(expected),
                                            "Prüfsumme (XOR), erwartet " + hexByte(expected)}});
    }
    if (decoded.ok())
        d.summary = summaryOf(*decoded);
    if (d.error) {
        const LocalText e = describeError(*d.error);
        d.summary = decoded.ok() ? LocalText{d.summary.en + " (" + e.en + ")",
                                             d.summary.de + " (" + e.de + ")"}
                                 : e;
    }
    return d;
}

} // namespace vt::dev::hart
