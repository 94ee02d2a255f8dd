// Field descriptions of SDO messages (CiA 301 §7.2.4.3) for the telegram inspector and the CLI.
#include "canopen/sdo.h"
#include "core/hex.h"

#include <string>

namespace vt::dev::canopen {
namespace {

std::string hex32(std::uint32_t v)
{
    return hexWord(static_cast<std::uint16_t>(v >> 16)) +
           hexWord(static_cast<std::uint16_t>(v)).substr(2);
}

std::string objectText(const Sdo &s)
{
    return hexWord(s.index) + "/" + std::to_string(s.subindex);
}

void describeBits(const Sdo &s, std::uint8_t byte0, std::vector<FieldSpan> &out)
{
    out.push_back({"sdo.cs", 0, 1, 1, std::to_string(byte0 >> 5),
                   directionOf(s.command) == Direction::Request && s.command != SdoCommand::Abort
                       ? LocalText{"client command specifier", "Client-Kommandospezifizierer"}
                       : LocalText{"command specifier", "Kommandospezifizierer"}});
    if (s.command == SdoCommand::InitiateDownloadRequest ||
        s.command == SdoCommand::InitiateUploadResponse) {
        if (s.expedited && s.sizeIndicated)
            out.push_back({"sdo.n",
                           0,
                           1,
                           1,
                           std::to_string((byte0 >> 2) & 0x03),
                           {"bytes without data (n)", "Bytes ohne Daten (n)"}});
        out.push_back({"sdo.e", 0, 1, 1, s.expedited ? "1" : "0",
                       s.expedited ? LocalText{"expedited transfer", "beschleunigte Übertragung"}
                                   : LocalText{"segmented transfer", "segmentierte Übertragung"}});
        out.push_back({"sdo.s", 0, 1, 1, s.sizeIndicated ? "1" : "0",
                       s.sizeIndicated ? LocalText{"size indicated", "Größe angegeben"}
                                       : LocalText{"size not indicated", "Größe nicht angegeben"}});
    }
    const bool segment = s.command == SdoCommand::DownloadSegmentRequest ||
                         s.command == SdoCommand::UploadSegmentResponse ||
                         s.command == SdoCommand::UploadSegmentRequest ||
                         s.command == SdoCommand::DownloadSegmentResponse;
    if (segment)
        out.push_back({"sdo.t", 0, 1, 1, s.toggle ? "1" : "0", {"toggle bit", "Toggle-Bit"}});
    if (s.command == SdoCommand::DownloadSegmentRequest ||
        s.command == SdoCommand::UploadSegmentResponse) {
        out.push_back({"sdo.n",
                       0,
                       1,
                       1,
                       std::to_string((byte0 >> 1) & 0x07),
                       {"bytes without data (n)", "Bytes ohne Daten (n)"}});
        out.push_back({"sdo.c", 0, 1, 1, s.last ? "1" : "0",
                       s.last ? LocalText{"last segment", "letztes Segment"}
                              : LocalText{"more segments follow", "weitere Segmente folgen"}});
    }
}

LocalText summaryOf(const Sdo &s, const std::optional<SdoChannel> &channel)
{
    LocalText what = commandText(s);
    if (s.command != SdoCommand::DownloadSegmentRequest &&
        s.command != SdoCommand::UploadSegmentRequest &&
        s.command != SdoCommand::DownloadSegmentResponse &&
        s.command != SdoCommand::UploadSegmentResponse && !isBlockTransfer(s.command)) {
        what.en += " " + objectText(s);
        what.de += " " + objectText(s);
    }
    if (s.expedited) {
        const std::string v =
            " = " + std::to_string(expeditedValue(s)) + " (" + std::to_string(s.data.size());
        what.en += v + (s.data.size() == 1 ? " byte)" : " bytes)");
        what.de += v + " Byte)";
    }
    if (s.command == SdoCommand::Abort) {
        const LocalText a = abortCodeText(s.abortCode);
        what.en += ": " + a.en;
        what.de += ": " + a.de;
    }
    if (channel) {
        const std::string n = std::to_string(channel->node);
        what.en = "node " + n + ": " + what.en;
        what.de = "Knoten " + n + ": " + what.de;
    }
    return what;
}

} // namespace

LocalText commandText(const Sdo &s)
{
    switch (s.command) {
    case SdoCommand::InitiateDownloadRequest:
        return s.expedited
                   ? LocalText{"initiate download (expedited write)",
                               "Download einleiten (beschleunigtes Schreiben)"}
                   : LocalText{"initiate segmented download", "segmentierten Download einleiten"};
    case SdoCommand::DownloadSegmentRequest: return {"download segment", "Download-Segment"};
    case SdoCommand::InitiateUploadRequest:
        return {"initiate upload (read)", "Upload einleiten (Lesen)"};
    case SdoCommand::UploadSegmentRequest:
        return {"upload segment request", "Upload-Segment anfordern"};
    case SdoCommand::BlockUploadRequest:
        return {"block upload (not supported)", "Block-Upload (nicht unterstützt)"};
    case SdoCommand::BlockDownloadRequest:
        return {"block download (not supported)", "Block-Download (nicht unterstützt)"};
    case SdoCommand::InitiateDownloadResponse:
        return {"download confirmed (write done)", "Download bestätigt (geschrieben)"};
    case SdoCommand::DownloadSegmentResponse:
        return {"download segment confirmed", "Download-Segment bestätigt"};
    case SdoCommand::InitiateUploadResponse:
        return s.expedited
                   ? LocalText{"upload response (value read)", "Upload-Antwort (gelesener Wert)"}
                   : LocalText{"initiate segmented upload", "segmentierten Upload einleiten"};
    case SdoCommand::UploadSegmentResponse: return {"upload segment", "Upload-Segment"};
    case SdoCommand::BlockDownloadResponse:
        return {"block download response (not supported)",
                "Block-Download-Antwort (nicht unterstützt)"};
    case SdoCommand::BlockUploadResponse:
        return {"block upload response (not supported)",
                "Block-Upload-Antwort (nicht unterstützt)"};
    case SdoCommand::Abort: return {"abort transfer", "Übertragung abbrechen"};
    }
    return {"unknown SDO command", "unbekanntes SDO-Kommando"};
}

Description describeSdo(std::span<const std::uint8_t> data, const DescribeOptions &options)
{
    Description d;
    d.protocol = "canopen-sdo";
    const auto channel = options.cobId ? sdoChannel(*options.cobId) : std::nullopt;
    const Direction direction = channel ? channel->direction : options.direction;
    if (options.cobId) {
        const std::string id = hexWord(static_cast<std::uint16_t>(*options.cobId & 0xFFFF));
        LocalText text{"COB-ID: not an SDO channel", "COB-ID: kein SDO-Kanal"};
        if (channel) {
            const std::string n = std::to_string(channel->node);
            text = channel->direction == Direction::Request
                       ? LocalText{"COB-ID: SDO request to node " + n + " (0x600 + node)",
                                   "COB-ID: SDO-Anfrage an Knoten " + n + " (0x600 + Knoten)"}
                       : LocalText{"COB-ID: SDO response from node " + n + " (0x580 + node)",
                                   "COB-ID: SDO-Antwort von Knoten " + n + " (0x580 + Knoten)"};
        }
        d.fields.push_back({"can.id", 0, 0, 0, id, text});
    }
    auto decoded = decodeSdo(data, direction);
    if (decoded.ok() && options.cobId && !channel) {
        d.error =
            DecodeError{DecodeErrc::UnexpectedCommand, 0, 0,
                        "COB-ID " + hexWord(static_cast<std::uint16_t>(*options.cobId & 0xFFFF)) +
                            " is not an SDO channel (0x581..0x5FF, 0x601..0x67F)"};
        decoded = *d.error;
    }
    if (!decoded.ok()) {
        d.error = decoded.error();
        if (!data.empty())
            d.fields.push_back(
                {"sdo.command", 0, 1, 0, hexByte(data.front()), {"command byte", "Kommandobyte"}});
        d.summary = describeError(*d.error);
        return d;
    }
    const Sdo &s = *decoded;
    const std::uint8_t byte0 = data.front();
    d.fields.push_back({"sdo.command", 0, 1, 0, hexByte(byte0), commandText(s)});
    if (isBlockTransfer(s.command)) {
        d.fields.push_back({"sdo.block",
                            1,
                            7,
                            0,
                            toHex(data.subspan(1)),
                            {"block transfer bytes (not interpreted)",
                             "Bytes der Blockübertragung (nicht ausgewertet)"}});
        d.summary = summaryOf(s, channel);
        return d;
    }
    describeBits(s, byte0, d.fields);
    const bool segmentData = s.command == SdoCommand::DownloadSegmentRequest ||
                             s.command == SdoCommand::UploadSegmentResponse;
    if (segmentData) {
        if (!s.data.empty())
            d.fields.push_back({"sdo.segment_data",
                                1,
                                s.data.size(),
                                0,
                                toHex(s.data),
                                {"segment data", "Segmentdaten"}});
    } else if (s.command != SdoCommand::UploadSegmentRequest &&
               s.command != SdoCommand::DownloadSegmentResponse) {
        d.fields.push_back({"sdo.index",
                            1,
                            2,
                            0,
                            hexWord(s.index),
                            {"object index (little-endian)", "Objektindex (Little-Endian)"}});
        d.fields.push_back(
            {"sdo.subindex", 3, 1, 0, std::to_string(s.subindex), {"sub-index", "Subindex"}});
        if (s.command == SdoCommand::Abort) {
            d.fields.push_back(
                {"sdo.abort_code", 4, 4, 0, hex32(s.abortCode), abortCodeText(s.abortCode)});
        } else if (s.expedited) {
            d.fields.push_back({"sdo.data",
                                4,
                                s.data.size(),
                                0,
                                toHex(s.data) + " (" + std::to_string(expeditedValue(s)) + ")",
                                {"data (little-endian)", "Daten (Little-Endian)"}});
        } else if (s.sizeIndicated) {
            d.fields.push_back({"sdo.size",
                                4,
                                4,
                                0,
                                std::to_string(s.size),
                                {"bytes to transfer", "zu übertragende Bytes"}});
        }
    }
    d.summary = summaryOf(s, channel);
    return d;
}

Description describeSdo(const CanFrame &frame)
{
    DescribeOptions o;
    o.cobId = frame.id;
    Description d = describeSdo(frame.payload(), o);
    if (!d.error && (frame.extended || frame.rtr || frame.errorFrame)) {
        d.error = DecodeError{DecodeErrc::UnexpectedCommand, 0, 0, "not an SDO frame"};
        d.summary = describeError(*d.error);
    }
    return d;
}

} // namespace vt::dev::canopen
