#include "fold_check.h"
#include "model/text_language.h"

#include <QCoreApplication>
#include <QStringList>

namespace vt::model {
namespace {

// The sentences of the checks, through tr() when they are shown; a finding keeps which sentence
// and its values, so a view that shows it again after a language change says it in the new one.
class FoldCheckText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::FoldCheck)

public:
    static QString source(FoldText text);
    static QString severity(FoldSeverity severity);
};

QString FoldCheckText::source(FoldText text)
{
    switch (text) {
    case FoldText::NoModules: return tr("The plan has no modules.");
    case FoldText::TooManyOpat:
        return tr("%1 modules: an OPAT node has the master and at most 7 CAN slaves (rotary "
                  "switch 1 … 7; OPAT manual §1.4).");
    case FoldText::TooManyDma:
        return tr("%1 modules: a DMA node addresses at most 32 modules (E22 = 1 … 32; DMA "
                  "Profibus Anleitung §1.5, DMA Profinet manual §1.5).");
    case FoldText::Cmd15Limit:
        return tr("%1 DMA modules: CMD 15 reaches E22 = 1 … 5 only. Modules above 5 can be "
                  "reached by CMD 3 / CMD 6 only and cannot be part of the cyclic PLC image (DMA "
                  "Profibus Anleitung §1.5, DMA Profinet manual §1.5). Plan at most 5 modules for "
                  "CMD 15.");
    case FoldText::ProductNumberUndecided:
        return tr("The product number \"%1\" does not decide the GSD file: HCS0220.GSD is "
                  "assumed. Product numbers 5 xxx xxx x1 … x4 use hcs0220.gsd, 5 005 xxx x5 use "
                  "hcs0ea7.gsd (DMA Profibus Anleitung §6.1.1).");
    case FoldText::ProductNumberMissing:
        return tr("No product number given: HCS0220.GSD is assumed. Product numbers 5 xxx xxx x1 "
                  "… x4 use hcs0220.gsd, 5 005 xxx x5 use hcs0ea7.gsd (DMA Profibus Anleitung "
                  "§6.1.1).");
    case FoldText::OpatMasterSadr:
        return tr("The first module (the one with the PROFIBUS interface) must always have SADR = "
                  "0 (OPAT manual §1.4).");
    case FoldText::OpatSlaveSwitch:
        return tr("Module %1 (%2): CAN slaves take rotary switch positions 1 … 7 only (OPAT "
                  "manual §1.4, §3.1).");
    case FoldText::E22Off:
        return tr("Module %1 (%2): E22 = 0 switches the module's bus function off; the node "
                  "cannot reach it.");
    case FoldText::E22Range: return tr("Module %1 (%2): E22 must be 1 … 32.");
    case FoldText::E22BeyondCmd15:
        return tr("Module %1 (%2): CMD 15 reaches E22 = 1 … 5 only; this module is reachable by "
                  "CMD 3 / CMD 6 only (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).");
    case FoldText::DuplicateSadr:
        return tr("Modules %1 share SADR %2: the red LED lights and the master reports exception "
                  "12 \"two or more slaves have the same slave address\" (OPAT manual §1.3.2, "
                  "§3.3). Set a different rotary switch position.");
    case FoldText::DuplicateE22:
        return tr("Modules %1 share E22 = %2: the node cannot tell them apart. Set E22 = 1 … n "
                  "from left to right (DMA Profibus Anleitung §1.3, DMA Profinet manual §1.3).");
    case FoldText::AddressGap:
        return tr("With %1 modules CMD 15 addresses %2 … %3; a module outside that range gets no "
                  "set values and the node answers exception 8 \"timeout slave, address wrong or "
                  "not installed\" (OPAT manual §3.3, DMA Profinet manual §4.3).");
    case FoldText::OpatSwitchOrder:
        return tr("Set the slaves' rotary switches in rising, consecutive order beginning with 1 "
                  "(OPAT manual §1.6).");
    case FoldText::DmaE22Order:
        return tr("Set E22 = 1 for the module on the left, rising towards the node module (DMA "
                  "Profibus Anleitung §1.3, DMA Profinet manual §1.3, §4.1).");
    case FoldText::SnumOpat:
        return tr("The PLC sends SNUM = %1 but the node has %2 modules (master + %3 slaves → SNUM "
                  "= %3).");
    case FoldText::SnumDma:
        return tr("The PLC sends SNUM = %1 but the node has %2 modules (SNUM = %3).");
    case FoldText::SnumRange:
        return tr("An SNUM outside %1 is answered with exception 7 \"invalid number of connected "
                  "slaves\".");
    case FoldText::SnumWaits:
        return tr("The node then waits for modules that are not installed: exception 8 \"timeout "
                  "slave, address wrong or not installed\".");
    case FoldText::SnumBeyond:
        return tr("The modules beyond SNUM get no set values and never answer.");
    case FoldText::SnumLength:
        return tr("SNUM also fixes the telegram length (3 + 5 bytes per module, up to %1); a GSD "
                  "module that is too short gives exception 9 (OPAT manual §3.1, §3.3; DMA "
                  "Profinet manual §4.1).");
    case FoldText::VersionUnknown:
        return tr("Module %1 (%2): software version not known; the layout of the manuals' worked "
                  "examples is assumed. Scan the node to fill it in.");
    case FoldText::VersionNotHere:
        return tr("Module %1 (%2): software V%3 does not belong here; the manual describes %4 for "
                  "this position.");
    case FoldText::NoLayout:
        return tr("Module %1 (%2): the manuals define no CMD 15 layout for software V%3 in mode "
                  "%4.");
    case FoldText::MixedModes:
        return tr("The modules run in different modes or software versions. Only the control-byte "
                  "and status-word bits of each module's own mode apply; the PLC must read "
                  "VALUE1/VALUE2 per SADR with that module's meaning (DMA Profibus Anleitung §6, "
                  "DMA Profinet manual §5).");
    case FoldText::OptionNotBus:
        return tr("Module %1 (%2): %3 is not a bus option of this module here; it is ignored.");
    case FoldText::OptionNotInVersion:
        return tr("Module %1 (%2): %3 does not exist in software V%4; it is ignored.");
    case FoldText::OptionOutOfRange: return tr("Module %1 (%2): %3 = %4 is outside %5 … %6 (%7).");
    case FoldText::E24Master:
        return tr("E24 = 126: the PROFIBUS master sets the address. Set it before power-up; the "
                  "address the master assigns then shows in E24 (OPAT manual §1.4).");
    case FoldText::E24Address:
        return tr("E24 = %1: the new PROFIBUS address becomes active only after a "
                  "power-down/power-up sequence (OPAT manual §1.4).");
    case FoldText::E28Stop:
        return tr("E28 = 0: a lost CAN slave gives error 7 and the master goes to the disabled "
                  "state (OPAT manual §5.7).");
    case FoldText::E28Flag:
        return tr("E28 = 1: a lost CAN slave sets the error bit, but the master remains in its "
                  "previous state (OPAT manual §5.7).");
    case FoldText::E28Ignore:
        return tr("E28 = 2: error 7 is ignored; the master ignores lost CAN slaves, so a lost "
                  "slave goes unnoticed by the PLC (OPAT manual §5.7).");
    case FoldText::E23Off:
        return tr("Module %1 (%2): E23 = 0 switches the bus telegram timeout off; the module does "
                  "not react when the PLC stops sending.");
    case FoldText::E17Analogue:
        return tr("Module %1 (%2): E17 = 0 keeps the analogue set value input active; set E17 = 2 "
                  "when the set value comes from the bus only.");
    case FoldText::E26Off:
        return tr("Module %1 (%2): E26 = 0 disables CAN; the master cannot reach the slaves (OPAT "
                  "manual §7).");
    case FoldText::CanBaudDiffers:
        return tr("The modules are given different CAN baud rates (E26): master and slaves must "
                  "use the same rate or the master loses its slaves (error 7, exception 5 "
                  "\"timeout (CAN connection)\").");
    case FoldText::CanBaudReboot:
        return tr("A CAN baud rate (E26) changed through PROFIBUS becomes active only after a "
                  "reboot (OPAT manual §7).");
    case FoldText::NodeDiffers:
        return tr("Module %1 (address %2) is planned as V%3 in mode %4, but the connected node's "
                  "module at that address runs V%5 in mode %6. The plan's options and the PLC "
                  "image would not fit it; scan the node or change the plan.");
    case FoldText::NodeMissing:
        return tr("Module %1 (address %2) is planned, but no module of the connected node "
                  "answers at that address.");
    case FoldText::NodeExtra:
        return tr("The connected node has a module at address %1 (V%2, mode %3) that the plan "
                  "does not contain.");
    }
    return {};
}

QString FoldCheckText::severity(FoldSeverity severity)
{
    switch (severity) {
    case FoldSeverity::Info: return tr("Note");
    case FoldSeverity::Warning: return tr("Warning");
    case FoldSeverity::Error: return tr("Error");
    }
    return {};
}

} // namespace

QString foldFindingText(const FoldFinding &finding)
{
    QStringList sentences;
    for (const FoldSentence &sentence : finding.sentences) {
        QString text = FoldCheckText::source(sentence.text);
        for (const FoldArg &arg : sentence.args) {
            if (const auto *address = std::get_if<FoldAddress>(&arg))
                text = text.arg(foldAddressText(*address));
            else
                text = text.arg(localText(std::get<dev::LocalText>(arg)));
        }
        sentences << text;
    }
    return sentences.join(QLatin1Char(' '));
}

QString foldSeverityText(FoldSeverity severity)
{
    return FoldCheckText::severity(severity);
}

} // namespace vt::model
