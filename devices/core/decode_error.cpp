#include "decode_error.h"

namespace vt::dev {

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
        out.de += ": " + error.detail;
    }
    return out;
}

} // namespace vt::dev
