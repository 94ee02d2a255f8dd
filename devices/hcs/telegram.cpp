#include "telegram.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"
#include "core/hex.h"

#include <optional>
#include <string>
#include <type_traits>

namespace vt::dev::hcs {

std::string_view familyName(Family family)
{
    return family == Family::Opat ? "opat" : "dma";
}

std::optional<Family> familyFromName(std::string_view name)
{
    if (name == "opat")
        return Family::Opat;
    if (name == "dma")
        return Family::Dma;
    return std::nullopt;
}

namespace {

bool isKnownCommand(std::uint8_t cmd)
{
    return cmd == kCmdRead || cmd == kCmdWrite || cmd == kCmdCyclic;
}

// Bytes after the telegram: an error unless the caller reads a padded process image.
std::optional<DecodeError> checkEnd(const ByteReader &r, const DecodeOptions &options)
{
    if (!r.atEnd() && !options.allowPadding)
        return tooLong(r,
                       std::to_string(r.data().size() - r.offset()) + " bytes after the telegram");
    return std::nullopt;
}

// Reads the 3-byte header (TADR, SADR/SNUM, CMD); the reader then stands at offset 3.
struct Header
{
    std::uint8_t tadr = 0;
    std::uint8_t address = 0;
    std::uint8_t cmd = 0;
};

std::optional<DecodeError> readHeader(ByteReader &r, Header &h)
{
    h.tadr = r.u8();
    h.address = r.u8();
    h.cmd = r.u8();
    if (r.failed())
        return truncated(r, "the header TADR SADR CMD needs 3 bytes");
    return std::nullopt;
}

DecodeError unexpected(std::uint8_t cmd, std::string_view expected)
{
    return decodeError(DecodeErrc::UnexpectedCommand, 2,
                       "got " + hexByte(cmd) + ", expected " + std::string(expected));
}

// The body of an error frame after its header: EXCE (OPAT manual §2.3).
Result<ExceptionResponse, DecodeError> exceptionBody(ByteReader &r, const Header &h,
                                                     const DecodeOptions &options)
{
    const auto base = static_cast<std::uint8_t>(h.cmd & ~kErrorBit);
    if (!isKnownCommand(base))
        return unexpected(h.cmd, "0x83, 0x86 or 0x8F");
    ExceptionResponse e{h.tadr, h.address, base, r.u8()};
    if (r.failed())
        return truncated(r, "an error response needs EXCE at byte 3");
    if (auto end = checkEnd(r, options))
        return *end;
    return e;
}

DecodeError deviceException(const ExceptionResponse &e)
{
    DecodeError err = decodeError(DecodeErrc::DeviceException, 3,
                                  "ERR " + hexByte(e.err()) + " EXCE " + std::to_string(e.code));
    err.deviceCode = e.code;
    return err;
}

Result<ReadRequest, DecodeError> readRequestBody(ByteReader &r, const Header &h,
                                                 const DecodeOptions &options)
{
    ReadRequest q{h.tadr, h.address, r.u16be(), r.u16be()};
    if (r.failed())
        return truncated(r, "a CMD 3 request has 7 bytes");
    if (auto end = checkEnd(r, options))
        return *end;
    return q;
}

Result<ReadResponse, DecodeError> readResponseBody(ByteReader &r, const Header &h,
                                                   const DecodeOptions &options)
{
    // OPAT manual §2.2: CNT = N*2, number of data bytes; the telegram has 4 + CNT bytes.
    const std::uint8_t cnt = r.u8();
    if (r.failed())
        return truncated(r, "a CMD 3 response needs CNT at byte 3");
    if (cnt % 2 != 0)
        return decodeError(DecodeErrc::BadLength, 3,
                           "CNT " + std::to_string(cnt) + " is odd; it counts 16-bit values");
    ReadResponse a{h.tadr, h.address, {}};
    a.values.reserve(cnt / 2u);
    for (unsigned i = 0; i < cnt / 2u; ++i)
        a.values.push_back(r.u16be());
    if (r.failed())
        return truncated(r, "CNT " + std::to_string(cnt) + " announces " + std::to_string(cnt) +
                                " data bytes");
    if (auto end = checkEnd(r, options))
        return *end;
    return a;
}

template<typename T>
Result<T, DecodeError> writeBody(ByteReader &r, const Header &h, const DecodeOptions &options)
{
    T w{h.tadr, h.address, r.u16be(), r.u16be()};
    if (r.failed())
        return truncated(r, "a CMD 6 telegram has 7 bytes");
    if (auto end = checkEnd(r, options))
        return *end;
    return w;
}

// Converts Result<T> into Result<Variant>.
template<typename V, typename T> Result<V, DecodeError> widen(Result<T, DecodeError> r)
{
    if (!r.ok())
        return r.error();
    return V{std::move(r).value()};
}

} // namespace

Bytes encode(const ReadRequest &q)
{
    ByteWriter w;
    w.u8(q.tadr).u8(q.sadr).u8(kCmdRead).u16be(q.firstId).u16be(q.count);
    return w.take();
}

Result<Bytes, DecodeError> encode(const ReadResponse &a)
{
    if (a.values.size() > 127)
        return decodeError(DecodeErrc::BadValue, 3,
                           std::to_string(a.values.size()) + " values do not fit the one-byte CNT");
    ByteWriter w;
    w.u8(a.tadr).u8(a.sadr).u8(kCmdRead).u8(static_cast<std::uint8_t>(a.values.size() * 2));
    for (std::uint16_t v : a.values)
        w.u16be(v);
    return w.take();
}

Bytes encode(const WriteRequest &q)
{
    ByteWriter w;
    w.u8(q.tadr).u8(q.sadr).u8(kCmdWrite).u16be(q.id).u16be(q.value);
    return w.take();
}

Bytes encode(const WriteResponse &a)
{
    ByteWriter w;
    w.u8(a.tadr).u8(a.sadr).u8(kCmdWrite).u16be(a.id).u16be(a.value);
    return w.take();
}

Bytes encode(const ExceptionResponse &e)
{
    ByteWriter w;
    w.u8(e.tadr).u8(e.sadr).u8(e.err()).u8(e.code);
    return w.take();
}

Result<Bytes, DecodeError> encode(const Request &request, Family family)
{
    return std::visit(
        [family](const auto &q) -> Result<Bytes, DecodeError> {
            using T = std::decay_t<decltype(q)>;
            if constexpr (std::is_same_v<T, CyclicRequest>)
                return encode(q, family);
            else
                return encode(q);
        },
        request);
}

Result<Bytes, DecodeError> encode(const Response &response)
{
    return std::visit([](const auto &a) -> Result<Bytes, DecodeError> { return encode(a); },
                      response);
}

namespace {

// The typed decoders share this: header, then CMD must be `cmd`; in a response the matching
// error frame (cmd | 0x80, OPAT manual §2.3) becomes DecodeErrc::DeviceException.
template<typename T, typename Body>
Result<T, DecodeError> decodeTyped(std::span<const std::uint8_t> frame,
                                   const DecodeOptions &options, std::uint8_t cmd, bool response,
                                   Body body)
{
    ByteReader r(frame);
    Header h;
    if (auto e = readHeader(r, h))
        return *e;
    const auto errorCmd = static_cast<std::uint8_t>(cmd | kErrorBit);
    if (response && h.cmd == errorCmd) {
        auto e = exceptionBody(r, h, options);
        return e.ok() ? deviceException(*e) : e.error();
    }
    if (h.cmd != cmd)
        return unexpected(h.cmd, std::to_string(cmd) +
                                     (response ? " or " + hexByte(errorCmd) : std::string()));
    return body(r, h);
}

} // namespace

Result<ReadRequest, DecodeError> decodeReadRequest(std::span<const std::uint8_t> frame,
                                                   const DecodeOptions &options)
{
    return decodeTyped<ReadRequest>(
        frame, options, kCmdRead, false,
        [&](ByteReader &r, const Header &h) { return readRequestBody(r, h, options); });
}

Result<ReadResponse, DecodeError> decodeReadResponse(std::span<const std::uint8_t> frame,
                                                     const DecodeOptions &options)
{
    return decodeTyped<ReadResponse>(
        frame, options, kCmdRead, true,
        [&](ByteReader &r, const Header &h) { return readResponseBody(r, h, options); });
}

Result<WriteRequest, DecodeError> decodeWriteRequest(std::span<const std::uint8_t> frame,
                                                     const DecodeOptions &options)
{
    return decodeTyped<WriteRequest>(
        frame, options, kCmdWrite, false,
        [&](ByteReader &r, const Header &h) { return writeBody<WriteRequest>(r, h, options); });
}

Result<WriteResponse, DecodeError> decodeWriteResponse(std::span<const std::uint8_t> frame,
                                                       const DecodeOptions &options)
{
    return decodeTyped<WriteResponse>(
        frame, options, kCmdWrite, true,
        [&](ByteReader &r, const Header &h) { return writeBody<WriteResponse>(r, h, options); });
}

Result<ExceptionResponse, DecodeError> decodeExceptionResponse(std::span<const std::uint8_t> frame,
                                                               const DecodeOptions &options)
{
    ByteReader r(frame);
    Header h;
    if (auto e = readHeader(r, h))
        return *e;
    if ((h.cmd & kErrorBit) == 0)
        return unexpected(h.cmd, "an error response (bit 7 set)");
    return exceptionBody(r, h, options);
}

Result<Request, DecodeError> decodeRequest(std::span<const std::uint8_t> frame,
                                           const DecodeOptions &options)
{
    ByteReader r(frame);
    Header h;
    if (auto e = readHeader(r, h))
        return *e;
    switch (h.cmd) {
    case kCmdRead: return widen<Request>(readRequestBody(r, h, options));
    case kCmdWrite: return widen<Request>(writeBody<WriteRequest>(r, h, options));
    case kCmdCyclic: return widen<Request>(decodeCyclicRequest(frame, options));
    default: return unexpected(h.cmd, "3, 6 or 15");
    }
}

Result<Response, DecodeError> decodeResponse(std::span<const std::uint8_t> frame,
                                             const DecodeOptions &options)
{
    ByteReader r(frame);
    Header h;
    if (auto e = readHeader(r, h))
        return *e;
    // OPAT manual §2.3: "Error, Bit 7 with command 0x03 is set".
    if ((h.cmd & kErrorBit) != 0)
        return widen<Response>(exceptionBody(r, h, options));
    switch (h.cmd) {
    case kCmdRead: return widen<Response>(readResponseBody(r, h, options));
    case kCmdWrite: return widen<Response>(writeBody<WriteResponse>(r, h, options));
    case kCmdCyclic: return widen<Response>(decodeCyclicResponse(frame, options));
    default: return unexpected(h.cmd, "3, 6, 15 or an error response");
    }
}

} // namespace vt::dev::hcs
