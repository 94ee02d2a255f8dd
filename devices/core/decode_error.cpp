#include "decode_error.h"

#include <regex>

namespace vt::dev {
namespace {

// The German side of a codec's detail. Codecs word their details in English for logs; the few
// fixed words of the checksum and length details are said in German here ("CRC 0x1234,
// berechnet 0x4321"); the rest of a detail is field names and numbers, the same in both.
std::string germanDetail(const std::string &detail)
{
    static const std::regex checksum(
        R"(^(CRC|checksum) (0x[0-9A-Fa-f]+), computed (0x[0-9A-Fa-f]+)$)");
    static const std::regex after(
        R"(^([0-9]+) bytes after the (CRC|checksum|ADU|PDU|PKW|PZD|value)$)");
    std::smatch m;
    if (std::regex_match(detail, m, checksum))
        return (m[1] == "CRC" ? std::string("CRC") : std::string("Prüfsumme")) + " " + m[2].str() +
               ", berechnet " + m[3].str();
    if (std::regex_match(detail, m, after)) {
        const std::string what = m[2].str();
        const std::string de = what == "checksum"               ? "der Prüfsumme"
                               : what == "value"                ? "dem Wert"
                               : what == "PZD"                  ? "den PZD"
                               : what == "ADU" || what == "PDU" ? "der " + what
                                                                : "dem " + what;
        return m[1].str() + " Bytes nach " + de;
    }
    if (detail == "the header is incomplete" || detail == "frame header incomplete")
        return "der Telegrammkopf ist unvollständig";
    return detail;
}

} // namespace

LocalText errcText(DecodeErrc code)
{
    switch (code) {
    case DecodeErrc::Truncated: return {"truncated", "unvollständig"};
    case DecodeErrc::TooLong:
        return {"extra bytes after the frame", "überzählige Bytes nach dem Telegramm"};
    case DecodeErrc::BadChecksum: return {"checksum error", "Prüfsummenfehler"};
    case DecodeErrc::BadLength: return {"inconsistent length", "widersprüchliche Länge"};
    case DecodeErrc::BadValue: return {"invalid value", "ungültiger Wert"};
    case DecodeErrc::UnexpectedCommand: return {"unknown command", "unbekanntes Kommando"};
    case DecodeErrc::DeviceException: return {"device exception", "Geräteausnahme"};
    }
    return {"unknown error", "unbekannter Fehler"};
}

LocalText describeError(const DecodeError &error)
{
    const LocalText what = errcText(error.code);
    const std::string at = std::to_string(error.offset);
    LocalText out{what.en + " at byte " + at, what.de + " bei Byte " + at};
    if (!error.detail.empty()) {
        out.en += ": " + error.detail;
        out.de += ": " + germanDetail(error.detail);
    }
    return out;
}

} // namespace vt::dev
