#include "canopen_adapter.h"

#include "access/hcs_rows.h"
#include "access/wire_value.h"
#include "canopen/can_frame.h"

namespace vt::dev::access {

namespace {

constexpr std::uint16_t kVersId = 0;  // OPAT manual §4 / DMA manuals: "Vers", raw = version × 100
constexpr std::uint16_t kModeId = 95; // E00, the mode of the module
constexpr std::size_t kHcsWordBytes = 2; // HCS parameters are 16-bit words (OPAT manual §2.1)

Reply mismatch()
{
    Reply reply;
    reply.status = ReplyStatus::Mismatch;
    return reply;
}

bool validNode(int module)
{
    return module >= 1 && module <= canopen::kMaxNodeId;
}

std::uint32_t lowBytes(std::uint32_t value, std::size_t width)
{
    return width >= 4 ? value : value & ((std::uint32_t{1} << (8 * width)) - 1);
}

} // namespace

CanopenProfile canopenProfileOf(DeviceProtocol device)
{
    return device == DeviceProtocol::Hcs ? CanopenProfile::Hcs : CanopenProfile::Dsp408;
}

std::optional<CanObject> canopenObjectOf(const ParamMeta &row, CanopenProfile profile)
{
    if (row.canopen)
        return row.canopen;
    // ARCHITECTURE.md "CAN": "HCS parameters use the manufacturer area 0x2000 + ID, sub 0".
    if (profile == CanopenProfile::Hcs && row.id && *row.id >= 0 &&
        *row.id <= 0xFFFF - CanopenAdapter::kHcsBase)
        return CanObject{static_cast<std::uint16_t>(CanopenAdapter::kHcsBase + *row.id), 0};
    return std::nullopt;
}

std::vector<Transaction> CanopenAdapter::planRead(int module,
                                                  std::span<const ParamMeta *const> rows) const
{
    std::vector<Transaction> plan;
    for (const ParamMeta *row : rows) {
        if (!row || !row->readable() || !canopenObjectOf(*row, m_profile))
            continue;
        if (m_profile == CanopenProfile::Dsp408 && wireBytes(row->type) == 0)
            continue; // text: no expedited transfer carries it
        plan.push_back(Transaction::read(module, {row}));
    }
    return plan;
}

std::vector<Transaction> CanopenAdapter::planIdentify(int module) const
{
    if (m_profile == CanopenProfile::Dsp408)
        return {Transaction::identify(module, 0), Transaction::identify(module, 1)};
    return planHcsIdentify(module);
}

std::optional<CanopenAdapter::Access> CanopenAdapter::accessOf(const Transaction &t) const
{
    if (t.kind == TransactionKind::Identify) {
        if (m_profile == CanopenProfile::Dsp408)
            return Access{CanObject{t.step == 0 ? kDeviceTypeObject : kCapabilityObject, 0}, 4};
        return Access{
            CanObject{static_cast<std::uint16_t>(kHcsBase + (t.step == 0 ? kVersId : kModeId)), 0},
            kHcsWordBytes};
    }
    if (t.rows.size() != 1 || !t.rows.front())
        return std::nullopt;
    const ParamMeta &row = *t.rows.front();
    const auto object = canopenObjectOf(row, m_profile);
    if (!object)
        return std::nullopt;
    const std::size_t width =
        m_profile == CanopenProfile::Hcs ? kHcsWordBytes : wireBytes(row.type);
    if (width == 0)
        return std::nullopt;
    return Access{*object, width};
}

std::optional<canopen::Sdo> CanopenAdapter::requestOf(const Transaction &t) const
{
    const auto access = accessOf(t);
    if (!access)
        return std::nullopt;
    if (t.kind != TransactionKind::Write)
        return canopen::uploadRequest(access->object.index, access->object.sub);
    if (t.values.size() != 1)
        return std::nullopt;
    std::optional<std::uint32_t> bits;
    if (m_profile == CanopenProfile::Hcs)
        bits = hcsWordOf(*t.rows.front(), t.values.front());
    else
        bits = rawToWireBits(*t.rows.front(), t.values.front());
    if (!bits)
        return std::nullopt;
    // CiA 301 §7.2.4.3: expedited, size indicated, little-endian.
    return canopen::expeditedDownload(access->object.index, access->object.sub, *bits,
                                      access->width);
}

Bytes CanopenAdapter::encode(const Transaction &t)
{
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    if (!validNode(t.module))
        return {};
    const auto sdo = requestOf(t);
    if (!sdo)
        return {};
    auto frame = canopen::toCanFrame(*sdo, static_cast<std::uint8_t>(t.module));
    if (!frame)
        return {};
    const auto image = canopen::toSocketCan(*frame);
    return Bytes(image.begin(), image.end());
}

std::size_t CanopenAdapter::expectedReplyBytes(const Transaction &) const
{
    return canopen::kSocketCanFrameSize;
}

double CanopenAdapter::valueFromBits(const Transaction &t, std::uint32_t bits) const
{
    if (t.kind == TransactionKind::Identify || t.rows.empty() || !t.rows.front())
        return static_cast<double>(bits);
    if (m_profile == CanopenProfile::Hcs)
        return registerToRaw(*t.rows.front(), static_cast<std::uint16_t>(bits & 0xFFFFu));
    return wireBitsToRaw(*t.rows.front(), bits);
}

Reply CanopenAdapter::sdoReply(const canopen::Sdo &sdo, const Transaction &t) const
{
    const auto access = accessOf(t);
    if (!access || sdo.index != access->object.index || sdo.subindex != access->object.sub)
        return mismatch();
    Reply reply;
    if (sdo.command == canopen::SdoCommand::Abort && t.kind == TransactionKind::Identify &&
        m_profile == CanopenProfile::Dsp408 && t.step == 1) {
        // No capability object: the device type alone identifies (identifyDsp408 says so).
        reply.identity.text = {
            "no capability object 0x605F (abort " + std::to_string(sdo.abortCode) + ")",
            "kein Fähigkeitenobjekt 0x605F (Abbruch " + std::to_string(sdo.abortCode) + ")"};
        return reply;
    }
    if (sdo.command == canopen::SdoCommand::Abort) {
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionCode = static_cast<int>(sdo.abortCode);
        reply.exceptionText = canopen::abortCodeText(sdo.abortCode);
        return reply;
    }
    if (t.kind == TransactionKind::Write) {
        if (sdo.command != canopen::SdoCommand::InitiateDownloadResponse)
            return mismatch();
        // CiA 301: the confirmation carries no value; the value is what was written.
        const auto request = requestOf(t);
        if (!request)
            return mismatch();
        reply.values.emplace_back(valueFromBits(t, canopen::expeditedValue(*request)));
        return reply;
    }
    if (sdo.command != canopen::SdoCommand::InitiateUploadResponse)
        return mismatch();
    if (!sdo.expedited) {
        // An object longer than 4 bytes: the session uses expedited transfers only.
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionText = {
            "the object needs a segmented transfer (more than 4 bytes)",
            "das Objekt braucht eine segmentierte Übertragung (mehr als 4 Byte)"};
        return reply;
    }
    if (sdo.sizeIndicated && sdo.data.size() != access->width) {
        reply.status = ReplyStatus::DeviceException;
        reply.exceptionText = {"the object has " + std::to_string(sdo.data.size()) +
                                   " bytes, the parameter " + std::to_string(access->width),
                               "das Objekt hat " + std::to_string(sdo.data.size()) +
                                   " Byte, der Parameter " + std::to_string(access->width)};
        return reply;
    }
    // Without size indication the low bytes of the four carry the value (CiA 301 §7.2.4.3, s = 0).
    const std::uint32_t bits = lowBytes(canopen::expeditedValue(sdo), access->width);
    const double value = valueFromBits(t, bits);
    reply.values.emplace_back(value);
    if (t.kind == TransactionKind::Identify) {
        if (m_profile == CanopenProfile::Dsp408 && t.step == 0) {
            reply.identity.deviceProfile = static_cast<std::uint16_t>(bits & 0xFFFFu);
            reply.identity.text = {"CiA 301 device type " + std::to_string(bits) + ", profile " +
                                       std::to_string(bits & 0xFFFFu),
                                   "CiA-301-Gerätetyp " + std::to_string(bits) + ", Profil " +
                                       std::to_string(bits & 0xFFFFu)};
        } else if (m_profile == CanopenProfile::Dsp408) {
            reply.identity.capability = bits;
        } else {
            (t.step == 0 ? reply.identity.versRaw : reply.identity.mode) = static_cast<int>(bits);
        }
    }
    return reply;
}

std::optional<Reply> CanopenAdapter::feed(std::span<const std::uint8_t> bytes, const Transaction &t)
{
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::optional<Reply> result;
    std::size_t used = 0;
    while (m_buffer.size() - used >= canopen::kSocketCanFrameSize) {
        const auto image =
            std::span<const std::uint8_t>(m_buffer).subspan(used, canopen::kSocketCanFrameSize);
        used += canopen::kSocketCanFrameSize;
        const auto frame = canopen::fromSocketCan(image);
        if (!frame)
            continue; // CAN FD length or an impossible id: not a frame the link would carry
        std::optional<Reply> reply;
        if (t.kind == TransactionKind::Raw) {
            reply = Reply{};
        } else if (!validNode(t.module) || frame->extended || frame->rtr || frame->errorFrame ||
                   frame->id != canopen::sdoResponseId(static_cast<std::uint8_t>(t.module))) {
            reply = mismatch(); // other traffic on the bus (other nodes, NMT, heartbeat, PDOs)
        } else {
            const auto sdo = canopen::decodeSdo(frame->payload(), Direction::Response);
            reply = sdo ? sdoReply(*sdo, t) : mismatch();
        }
        reply->frame.assign(image.begin(), image.end());
        if (offerReply(result, std::move(*reply)))
            break;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(used));
    return result;
}

void CanopenAdapter::resetFraming()
{
    m_buffer.clear();
}

} // namespace vt::dev::access
