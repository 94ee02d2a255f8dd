#include "auto_detect.h"

#include "canopen/can_frame.h"
#include "hart/frame.h"
#include "inspect/logged_frame.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"

#include <algorithm>

namespace vt::dev::inspect {
namespace {

constexpr Direction kDirections[] = {Direction::Request, Direction::Response};
constexpr hcs::Family kFamilies[] = {hcs::Family::Dma, hcs::Family::Opat};

bool decodes(std::span<const std::uint8_t> bytes, FrameFormat protocol, Direction direction,
             hcs::Family family, bool padded)
{
    AnyOptions o;
    o.protocol = protocol;
    o.direction = direction;
    o.family = family;
    // A PLC's process image is the gateway telegram plus padding (DMA Profinet manual §4.5.4).
    const auto d =
        padded ? describeLogged(LinkProtocol::NodeImage, bytes, o) : describeAny(bytes, o);
    return d.ok() && d->ok();
}

void tryDirections(Candidate &c, std::span<const std::uint8_t> bytes, bool familyMatters,
                   bool padded)
{
    for (Direction dir : kDirections) {
        bool any = false;
        for (hcs::Family fam : kFamilies) {
            if (!familyMatters && fam != kFamilies[0])
                continue;
            if (decodes(bytes, c.protocol, dir, fam, padded)) {
                any = true;
                if (familyMatters &&
                    std::find(c.families.begin(), c.families.end(), fam) == c.families.end())
                    c.families.push_back(fam);
            }
        }
        if (any)
            c.directions.push_back(dir);
    }
}

// Tries both directions (and both HCS families where they matter); nullopt when nothing decodes.
std::optional<Candidate> tryProtocol(std::span<const std::uint8_t> bytes, FrameFormat protocol,
                                     bool strong)
{
    Candidate c;
    c.protocol = protocol;
    c.strong = strong;
    const bool familyMatters =
        protocol == FrameFormat::Gateway || protocol == FrameFormat::Profidrive;
    tryDirections(c, bytes, familyMatters, false);
    // Not a bare telegram: a process image with padding? Only then, so that padding never hides
    // the SNUM rule of the family the telegram fits exactly.
    if (c.directions.empty() && protocol == FrameFormat::Gateway)
        tryDirections(c, bytes, true, true);
    if (c.directions.empty())
        return std::nullopt;
    return c;
}

bool hasHartPreambles(std::span<const std::uint8_t> bytes)
{
    // HART-7 manual §2.3: "three or more" preambles; tools often drop one, so two are accepted.
    return bytes.size() >= 2 && bytes[0] == hart::kPreamble && bytes[1] == hart::kPreamble;
}

bool hasMbap(std::span<const std::uint8_t> bytes)
{
    // Modbus Messaging Implementation Guide §3.1.3: protocol id 0 and a length that matches.
    const auto mbap = modbus::decodeMbap(bytes);
    return mbap.ok() && mbap->aduSize() == bytes.size();
}

// A Modbus RTU frame with a wrong CRC: its header announces exactly its length, and a read asks
// for 1..125 registers (Modbus Application Protocol V1.1b3 §6.3), so zero padding is no request.
std::optional<Candidate> rtuWithBadCrc(std::span<const std::uint8_t> bytes)
{
    if (bytes.size() < 5 || modbus::rtuCrcOk(bytes) || bytes[0] > 247)
        return std::nullopt;
    Candidate c;
    c.protocol = FrameFormat::ModbusRtu;
    c.badCrc = true;
    for (Direction dir : kDirections) {
        const auto length = modbus::rtuFrameLength(bytes, dir);
        if (!length || *length != bytes.size())
            continue;
        if (dir == Direction::Request && bytes[1] == 3) {
            const int count = (bytes[4] << 8) | bytes[5];
            if (count < 1 || count > 125)
                continue;
        }
        c.directions.push_back(dir);
    }
    if (c.directions.empty())
        return std::nullopt;
    return c;
}

} // namespace

Detection detectProtocol(std::span<const std::uint8_t> bytes, std::optional<std::uint32_t> cobId)
{
    Detection out;
    if (bytes.empty())
        return out;
    if (cobId) {
        Candidate c;
        c.protocol = FrameFormat::Canopen;
        c.strong = true;
        AnyOptions o;
        o.protocol = FrameFormat::Canopen;
        o.cobId = cobId;
        const auto d = describeAny(bytes, o);
        if (d.ok() && d->ok()) {
            c.directions.push_back(o.direction); // the COB-ID decides; the option is ignored
            out.candidates.push_back(c);
            out.chosen = 0;
        }
        return out;
    }
    std::vector<Candidate> strong;
    std::vector<Candidate> weak;
    auto add = [](std::vector<Candidate> &list, std::optional<Candidate> c) {
        if (c)
            list.push_back(std::move(*c));
    };
    // Modbus over Serial Line §2.5.1.2: CRC-16, low byte first.
    if (bytes.size() >= 4 && modbus::rtuCrcOk(bytes))
        add(strong, tryProtocol(bytes, FrameFormat::ModbusRtu, true));
    if (bytes.size() >= modbus::kMbapSize + 1 && hasMbap(bytes))
        add(strong, tryProtocol(bytes, FrameFormat::ModbusTcp, true));
    if (hasHartPreambles(bytes))
        add(strong, tryProtocol(bytes, FrameFormat::Hart, true));
    if (bytes.size() == canopen::kSocketCanFrameSize) {
        const Description d = describeSocketCanImage(bytes);
        if (d.ok()) {
            Candidate c;
            c.protocol = FrameFormat::Canopen;
            c.strong = true;
            c.directions = {Direction::Request, Direction::Response};
            strong.push_back(c);
        }
    }
    add(weak, tryProtocol(bytes, FrameFormat::Gateway, false));
    // OPAT manual §5.6: telegram 1 (4 bytes) followed by a CMD 15 telegram; four bytes alone
    // are any four bytes.
    if (bytes.size() >= 8)
        add(weak, tryProtocol(bytes, FrameFormat::Profidrive, false));
    if (bytes.size() == 8) {
        add(weak, tryProtocol(bytes, FrameFormat::Pkw, false));
        add(weak, tryProtocol(bytes, FrameFormat::Canopen, false));
    }
    if (bytes.size() == 14) // ED1/SD1 manual §4.5.1 telegram type 1: PKW + PZD
        add(weak, tryProtocol(bytes, FrameFormat::Pzd, false));

    const auto damaged = strong.empty() ? rtuWithBadCrc(bytes) : std::nullopt;
    out.candidates = strong;
    if (damaged)
        out.candidates.push_back(*damaged);
    out.candidates.insert(out.candidates.end(), weak.begin(), weak.end());
    if (strong.size() == 1)
        out.chosen = 0;
    else if (strong.empty() && (damaged || weak.size() == 1))
        out.chosen = 0;
    return out;
}

} // namespace vt::dev::inspect
