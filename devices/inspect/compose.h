// Frame composer for the inspector: builds a request from fields with the codecs' own encoders
// (HCS CMD 3/6/15, Modbus RTU/TCP FC 3/6, DSP-408 PKW, HART, CANopen SDO), says whether it
// changes the device (writes need a confirmation) and which link protocol can carry it.
#pragma once

#include "core/byte_writer.h"
#include "core/result.h"
#include "hcs/cmd15.h"
#include "hcs/types.h"
#include "inspect/describe_any.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vt::dev::inspect {

enum class ComposeKind {
    GatewayRead,    // CMD 3 (OPAT manual §2.1)
    GatewayWrite,   // CMD 6 (OPAT manual §2.4)
    GatewayCyclic,  // CMD 15 (OPAT manual §3.1, DMA Profinet manual §4.1)
    ModbusRead,     // FC 3, RTU or TCP
    ModbusWrite,    // FC 6
    PkwRead,        // AK 1 (ED1/SD1 manual §4.6)
    PkwWrite,       // AK 2 / 3 / 10 by width
    HartCommand,    // any command with data bytes (HART-7 manual §2.3)
    HartParamRead,  // commands 128 / 130 / 132 (HART-7 manual §4.4.1)
    HartParamWrite, // commands 129 / 131 / 133
    SdoUpload,      // CiA 301 §7.2.4.3.6 initiate upload
    SdoDownload,    // CiA 301 §7.2.4.3.3 expedited download
};

struct ComposeSpec
{
    ComposeKind kind = ComposeKind::GatewayRead;
    hcs::Family family = hcs::Family::Dma;     // CMD 15 SNUM rule
    long long tadr = 0x23, sadr = 0;           // gateway
    long long unit = 1;                        // Modbus unit id
    bool modbusTcp = false;                    // MBAP instead of RTU framing
    long long transaction = 1;                 // Modbus TCP transaction id
    long long id = 0;                          // HCS parameter ID = Modbus register
    long long count = 1;                       // CMD 3 / FC 3
    long long value = 0;                       // writes (16-bit words; PKW / HART / SDO: by width)
    std::vector<hcs::ModuleSetpoints> modules; // CMD 15
    long long ind = 0, pnu = 0, instance = 0;  // PKW, HART 128..133
    int width = 2;                             // PKW / HART / SDO value bytes: 1, 2 or 4
    long long pollAddress = 0;                 // HART short frame (no long address given)
    std::optional<std::uint16_t> hartDeviceType; // HART long frame when set
    std::uint32_t hartDeviceId = 0;
    long long hartCommand = 0;
    Bytes hartData;
    long long node = 1;                     // CANopen node
    long long index = 0x2000, subindex = 0; // SDO object
};

struct ComposedFrame
{
    FrameFormat protocol = FrameFormat::Gateway;
    Bytes bytes;                        // the frame; SDO: the 8 data bytes
    std::optional<std::uint32_t> cobId; // SDO
    bool writes = false;                // changes the device: confirm before sending
    // The link protocol that carries this frame; nullopt = none of ValveTune's links does (PKW
    // travels on PROFIBUS DP, which needs a master card).
    std::optional<LinkProtocol> link;
};

// Why compose() failed: an English reason as the manuals name the fields (the CLI, logs), and for a
// field out of range the ComposeSpec member and its range, so that a window names the field as
// it labels it ("Count" for the gateway's N).
struct ComposeError
{
    explicit ComposeError(std::string why, std::string member = {}, long long low = 0,
                          long long high = 0)
        : reason(std::move(why)), field(std::move(member)), min(low), max(high)
    {
    }
    std::string reason;
    std::string field; // "count", "tadr" …; empty when no one field is to blame
    long long min = 0, max = 0;
};

Result<ComposedFrame, ComposeError> compose(const ComposeSpec &spec);

// The bytes the frame's link sends: the SocketCAN image on CANopen, the telegram padded to
// `imageBytes` on the node image, the frame itself otherwise.
Bytes wireBytes(const ComposedFrame &frame, std::size_t imageBytes = 0);

} // namespace vt::dev::inspect
