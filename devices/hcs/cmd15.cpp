#include "cmd15.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"
#include "core/hex.h"

#include <string>

namespace vt::dev::hcs {

std::size_t maxCyclicModules(Family family)
{
    // OPAT manual §3.1: master + "Maximum 7" slaves; DMA Profinet manual §4.1: "Maximum 5".
    return family == Family::Opat ? 8 : 5;
}

std::optional<std::size_t> modulesForSnum(Family family, std::uint8_t snum)
{
    if (family == Family::Opat)
        return snum <= 7 ? std::optional<std::size_t>(std::size_t{snum} + 1) : std::nullopt;
    return snum >= 1 && snum <= 5 ? std::optional<std::size_t>(snum) : std::nullopt;
}

std::optional<std::uint8_t> snumForModules(Family family, std::size_t modules)
{
    if (modules < 1 || modules > maxCyclicModules(family))
        return std::nullopt;
    return static_cast<std::uint8_t>(family == Family::Opat ? modules - 1 : modules);
}

std::uint8_t moduleAddress(Family family, std::size_t index)
{
    // OPAT manual §1.4: the master is SADR 0, slaves 1..7; DMA Profinet manual §4.1: E22 = 1..5.
    return static_cast<std::uint8_t>(family == Family::Opat ? index : index + 1);
}

Result<Bytes, DecodeError> encode(const CyclicRequest &request, Family family)
{
    const auto snum = snumForModules(family, request.modules.size());
    if (!snum)
        return decodeError(DecodeErrc::BadValue, 1,
                           std::to_string(request.modules.size()) + " modules; " +
                               std::string(familyName(family)) + " allows 1.." +
                               std::to_string(maxCyclicModules(family)));
    ByteWriter w;
    w.u8(request.tadr).u8(*snum).u8(kCmdCyclic);
    for (const ModuleSetpoints &m : request.modules)
        w.u8(m.control)
            .u16be(static_cast<std::uint16_t>(m.value1))
            .u16be(static_cast<std::uint16_t>(m.value2));
    return w.take();
}

Bytes encode(const CyclicResponse &a)
{
    ByteWriter w;
    w.u8(a.tadr).u8(a.sadr).u8(kCmdCyclic).u16be(a.status);
    w.u16be(static_cast<std::uint16_t>(a.value1)).u16be(static_cast<std::uint16_t>(a.value2));
    return w.take();
}

Result<CyclicRequest, DecodeError> decodeCyclicRequest(std::span<const std::uint8_t> frame,
                                                       const DecodeOptions &options)
{
    ByteReader r(frame);
    CyclicRequest q;
    q.tadr = r.u8();
    const std::uint8_t snum = r.u8();
    const std::uint8_t cmd = r.u8();
    if (r.failed())
        return truncated(r, "the header TADR SNUM CMD needs 3 bytes");
    if (cmd != kCmdCyclic)
        return decodeError(DecodeErrc::UnexpectedCommand, 2,
                           "got " + hexByte(cmd) + ", expected 15 (0x0F)");
    const auto modules = modulesForSnum(options.family, snum);
    if (!modules)
        return decodeError(DecodeErrc::BadValue, 1,
                           "SNUM " + std::to_string(snum) + " is outside " +
                               (options.family == Family::Opat ? std::string("0..7 (OPAT)")
                                                               : std::string("1..5 (DMA)")));
    q.modules.reserve(*modules);
    for (std::size_t i = 0; i < *modules; ++i) {
        ModuleSetpoints m;
        m.control = r.u8();
        m.value1 = r.i16be();
        m.value2 = r.i16be();
        q.modules.push_back(m);
    }
    if (r.failed())
        return truncated(r, "SNUM " + std::to_string(snum) + " announces " +
                                std::to_string(kCyclicHeaderSize + kCyclicModuleSize * *modules) +
                                " bytes");
    if (!r.atEnd() && !options.allowPadding)
        return tooLong(r, std::to_string(frame.size() - r.offset()) + " bytes after the telegram");
    return q;
}

Result<CyclicResponse, DecodeError> decodeCyclicResponse(std::span<const std::uint8_t> frame,
                                                         const DecodeOptions &options)
{
    ByteReader r(frame);
    CyclicResponse a;
    a.tadr = r.u8();
    a.sadr = r.u8();
    const std::uint8_t cmd = r.u8();
    if (r.failed())
        return truncated(r, "the header TADR SADR CMD needs 3 bytes");
    if (cmd == (kCmdCyclic | kErrorBit)) {
        // OPAT manual §3.3: "ERR Error code: 0x8F = write failed", then EXCE.
        const std::uint8_t exce = r.u8();
        if (r.failed())
            return truncated(r, "an error response needs EXCE at byte 3");
        if (!r.atEnd() && !options.allowPadding)
            return tooLong(r, "an error response has 4 bytes");
        DecodeError e =
            decodeError(DecodeErrc::DeviceException, 3, "ERR 0x8F EXCE " + std::to_string(exce));
        e.deviceCode = exce;
        return e;
    }
    if (cmd != kCmdCyclic)
        return decodeError(DecodeErrc::UnexpectedCommand, 2,
                           "got " + hexByte(cmd) + ", expected 15 (0x0F) or 0x8F");
    a.status = r.u16be();
    a.value1 = r.i16be();
    a.value2 = r.i16be();
    if (r.failed())
        return truncated(r, "a CMD 15 response has 9 bytes");
    if (!r.atEnd() && !options.allowPadding)
        return tooLong(r, std::to_string(frame.size() - r.offset()) + " bytes after the telegram");
    return a;
}

} // namespace vt::dev::hcs
