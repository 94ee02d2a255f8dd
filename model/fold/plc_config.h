// The PLC side of a fold plan: which GSD/GSDML file and module to install, the
// CMD 15 output and input images byte by byte per module, control/status bits per module mode and
// an example telegram built with the CMD 15 codec. Pure value, built from a FoldPlan. Qt-free (the
// fuzz build has no Qt): its texts name a sentence and its values, and plcText()
// (plc_config_text.cpp) says them through tr() when they are shown.
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "fold_plan.h"
#include "hcs/cmd15.h"
#include "hcs/profiles.h"
#include "hcs/status_bits.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class QString;

namespace vt::model {

// One sentence of the sheet; its %1, %2 … are filled with PlcText::args in order.
enum class PlcTextId {
    NoModules,
    TooManyOpat,                 // modules
    TooManyDma,                  // modules
    OpatGsd,                     // slaves, output bytes
    ProfinetGsd,                 // output bytes
    Ea7Gsd,                      // output bytes
    ProfibusGsd,                 // output bytes
    ProfibusGsdUniversal,        // output bytes
    ProfibusGsdAssumed,          // output bytes
    ProfibusGsdUniversalAssumed, // output bytes
    TadrOut,
    SnumOpat, // slaves
    SnumDma,  // modules
    CmdOut,
    ControlByte,
    ValueHigh,          // VALUE1/2, meaning
    ValueLow,           // VALUE1/2, meaning
    ValueHighParameter, // VALUE1/2, parameter, meaning
    ValueLowParameter,  // VALUE1/2, parameter, meaning
    TadrIn,
    SadrIn, // address range
    CmdIn,
    StatusHigh,
    StatusLow,
    AnswerHigh, // VALUE1/2
    AnswerLow,  // VALUE1/2
};

struct PlcText
{
    PlcTextId id = PlcTextId::NoModules;
    std::vector<dev::LocalText> args; // numbers and names; meanings from devices/ in both languages

    bool operator==(const PlcText &) const = default;
};

// The sentence in the catalogue in force, its {en, de} values in `lang` (Qt; plc_config_text.cpp).
QString plcText(const PlcText &text, dev::Language lang);

// One byte of the output (PLC → node, the CMD 15 request) or input (node → PLC, the 9-byte
// response) image. Offsets are from the start of the telegram: PLC address = start address +
// offset.
struct PlcImageByte
{
    int offset = 0;
    int module = -1;   // index into FoldPlan::modules; -1 = telegram header / multiplexed
    std::string field; // the manuals' name: "TADR", "SNUM", "CMD", "DAT2.1", "DAT2.2H", "DAT.1L"
    PlcText text;      // "control byte (special functions)", "VALUE1 high byte: A1.01 …"

    bool operator==(const PlcImageByte &) const = default;
};

// Per module: where it sits in the output image and what its bytes and bits mean in its mode.
struct PlcModuleSection
{
    int module = 0; // index into FoldPlan::modules
    int sadr = 0;   // address in the telegram (OPAT 0..7, DMA E22 1..5)
    dev::hcs::Profile profile = dev::hcs::Profile::DmaV15Mode1; // CMD 15 layout of the meanings
    int outputFirst = 0;  // first output byte (its control byte DATx.1)
    int outputLength = 0; // always dev::hcs::kCyclicModuleSize (5)
    // Only the bits of the module's own mode apply (DMA Profibus Anleitung §6, DMA Profinet
    // manual §5: "only the bits for the control-byte and the status-word for the certain DMA
    // module is useable"); BitMeaning::used marks them.
    std::array<dev::hcs::BitMeaning, 8> controlBits{};
    std::array<dev::hcs::BitMeaning, 8> statusHighBits{};
    std::array<dev::hcs::BitMeaning, 8> statusLowBits{};
};

struct PlcConfig
{
    FoldNode node = FoldNode::DmaProfibus;
    int modules = 0;
    int snum = 0; // SNUM in the request (OPAT: slaves = modules − 1; DMA: modules)
    std::string
        gsdFile; // "HCS0D68.GSD", "HCS0220.GSD", "hcs0ea7.gsd", "GSDML-V2.2-HCS-DMA-XX_PN-….xml"
    std::string gsdDevice; // catalogue entry: "OPAT - Profibus", "DMA-2 - Profibus", "DMA-22-XX", …
    std::string gsdModule;     // "CMD15 1M 4S IN/OUT 9/28", "CMD15 3fold 9B-I 18B-O (kons)", …
    PlcText gsdNote;           // why this file and module, with the manual section
    int outputBytes = 0;       // CMD 15 request length: 3 + 5 × modules (8..43)
    int inputBytes = 0;        // CMD 15 response length: 9
    int moduleOutputBytes = 0; // bytes the GSD module reserves (≥ outputBytes; else exception 9)
    int moduleInputBytes = 0;
    std::vector<PlcImageByte> output; // every byte of the request, in order
    std::vector<PlcImageByte> input;  // every byte of the response, in order (multiplexed)
    std::vector<PlcModuleSection> sections;
    dev::hcs::CyclicRequest exampleRequest; // TADR 0x01, each module BUS enable and example values
    dev::Bytes exampleRequestBytes;         // encoded with dev::hcs::encode
    std::string source;                     // manual sections the whole sheet rests on
};

// Fails with a sentence saying why when the plan cannot be served by one CMD 15 telegram
// (no modules, DMA > 5, OPAT > 8 — usage errors for the CLI). Other problems (duplicates, modes)
// are the checks' job (checkFoldPlan); unknown layouts fall back to the family default profile.
dev::Result<PlcConfig, PlcText> buildPlcConfig(const FoldPlan &plan);

// GSD/GSDML choice alone (used by buildPlcConfig and the wizard's product-number field).
struct GsdChoice
{
    std::string file;
    std::string device;
    std::string module;
    int moduleOutputBytes = 0;
    int moduleInputBytes = 0;
    PlcText note;
    bool productNumberDecided = true; // false: DMA Profibus without a usable product number
};
GsdChoice chooseGsd(FoldNode node, std::size_t modules, const std::string &productNumber);

} // namespace vt::model
