// The Wandfluh ED1/SD1 through its PROFIBUS-DP cyclic image as a PC reaches it over TCP
// (ARCHITECTURE.md "Wandfluh ED1/SD1 online"): the raw output / input images exchanged cyclically
// (LinkProtocol::Dsp408Image, 14 bytes each way, telegram type 1), or the registers of a
// PROFIBUS-master gateway (LinkProtocol::Dsp408Gateway: FC 16 writes, FC 3 / FC 4 reads,
// dsp408/gateway.h). On top runs the DSP-408 PKW handshake of the ED1/SD1 manual §4.6: one
// request at a time, repeated every cycle until the input image carries the response whose AK,
// PNU and IND answer it (dsp408::answers); AK 7 is the device's refusal with the §4.6 error
// number. PZD (§4.5.2): control word and set value are the adapter's process data, sent in
// every image and changed only by a write of db_ControlWord or dpc_SetpointVal.
//
// A response only counts when it cannot be an older one: before a request whose IND and PNU an
// earlier request since the last cleared channel had (a read-back after a write, a retry, the
// first request of a connection), the adapter sends "no instruction" (AK 0) and waits for the
// AK 0 response first (§4.6 table: 0 → 0), so a late or repeated response is never taken for
// the new request's.
// Owner: one session; single-threaded.
#pragma once

#include "access/transaction.h"
#include "dsp408/gateway.h"
#include "dsp408/options.h"
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace vt::dev::access {

struct Dsp408LinkOptions
{
    dsp408::Options layout;     // IND byte and PZD word order (ARCHITECTURE.md "Byte order")
    dsp408::GatewayMap gateway; // Dsp408Gateway only
};

// ED1/SD1 manual §4.8.7: db_Capability, IND 0, PNU 50, uint32 — what identifies the ED1/SD1.
inline constexpr std::uint8_t kCapabilityInd = 0;
inline constexpr std::uint16_t kCapabilityPnu = 50;

class Dsp408Adapter : public ProtocolAdapter
{
public:
    // `carrier`: Dsp408Image or Dsp408Gateway.
    explicit Dsp408Adapter(LinkProtocol carrier, Dsp408LinkOptions options = {});

    LinkProtocol protocol() const override { return m_carrier; }

    // One PKW read per readable row with IND (0..255) and PNU (≤ 0x7FF) and a numeric type.
    std::vector<Transaction> planRead(int module,
                                      std::span<const ParamMeta *const> rows) const override;
    // One PKW read of db_Capability (§4.8.7).
    std::vector<Transaction> planIdentify(int module) const override;

    // Starts an attempt: the first image (or gateway write). Empty for a row without IND / PNU,
    // a value the row's type cannot hold, a text, a gateway unit outside 0..255.
    Bytes encode(const Transaction &t) override;
    // One input image (the gateway's read answer).
    std::size_t expectedReplyBytes(const Transaction &t) const override;
    // Whole images (gateway: whole ADUs of the outstanding Modbus transaction); Progress while
    // the handshake goes on, Ok / DeviceException when the answer is there.
    std::optional<Reply> feed(std::span<const std::uint8_t> bytes, const Transaction &t) override;
    void resetFraming() override;

    const Dsp408LinkOptions &options() const { return m_options; }
    // The process data sent in every image, and the last seen (status word, actual value).
    const dsp408::PzdSetpoint &pzdOut() const { return m_pzdOut; }
    const std::optional<dsp408::PzdActual> &pzdIn() const { return m_pzdIn; }

private:
    enum class Phase { Clear, Request, PzdWrite };
    enum class Wait { Image, WriteAck, ReadAnswer };

    std::optional<dsp408::Pkw> requestOf(const Transaction &t) const;
    bool isPzdWrite(const Transaction &t) const;
    bool mayStillShow(const dsp408::Pkw &request) const;
    // The bytes that put `pkw` on the wire: a whole output image, or the gateway's PKW registers.
    Bytes sendPkw(const dsp408::Pkw &pkw);
    Bytes readInput();
    Bytes writeRegisters(std::uint16_t offset, std::vector<std::uint16_t> values);
    std::optional<Reply> onImage(std::span<const std::uint8_t> image, const Transaction &t);
    std::optional<Reply> onAdu(std::span<const std::uint8_t> adu, const Transaction &t);
    Reply answerOf(const dsp408::Pkw &response, const Transaction &t) const;

    LinkProtocol m_carrier;
    Dsp408LinkOptions m_options;
    dsp408::PzdSetpoint m_pzdOut;
    std::optional<dsp408::PzdActual> m_pzdIn;
    // Requests sent since the device last answered AK 0: their responses may still show.
    std::vector<dsp408::Pkw> m_uncleared;
    bool m_channelUnknown = true; // a new connection: anything may be in the input image
    // The attempt on the wire.
    Phase m_phase = Phase::Request;
    Wait m_wait = Wait::Image;
    dsp408::Pkw m_request;
    std::uint16_t m_transaction = 0; // gateway: Modbus transaction of the ADU outstanding
    std::uint8_t m_unit = 1;         // gateway: Modbus unit of the attempt
    Bytes m_buffer;
};

} // namespace vt::dev::access
