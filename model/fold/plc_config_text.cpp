#include "model/fold/plc_config.h"

#include <QCoreApplication>
#include <QString>

namespace vt::model {
namespace {

// The sentences of the PLC sheet, through tr() when they are shown; a PlcText keeps which
// sentence and its values, so the sheet says them again in the language in force.
class PlcConfigText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::PlcConfig)

public:
    static QString source(PlcTextId id);
};

QString PlcConfigText::source(PlcTextId id)
{
    switch (id) {
    case PlcTextId::NoModules: return tr("The plan has no modules.");
    case PlcTextId::TooManyOpat:
        return tr("%1 OPAT modules: one CMD 15 telegram reaches the master and at most 7 CAN "
                  "slaves (8 modules; OPAT manual §1.6, §3.1).");
    case PlcTextId::TooManyDma:
        return tr("%1 DMA modules: CMD 15 reaches E22 = 1 … 5 only; modules above 5 are "
                  "reachable by CMD 3 / CMD 6 only (DMA Profibus Anleitung §1.5, DMA Profinet "
                  "manual §1.5).");
    case PlcTextId::OpatGsd:
        return tr("OPAT manual §1.1 (GSD file) and §4.1 (HW Config: the CMD 15 module for the "
                  "master and %1 slave(s); output at least %2 bytes, input at least 9 bytes).");
    case PlcTextId::ProfinetGsd:
        return tr("DMA Profinet manual §1.1 (GSDML file) and §4.5.4 (one 42-byte IN/OUT module "
                  "serves every fold; the CMD 15 telegram uses the first %1 output and 9 input "
                  "bytes).");
    case PlcTextId::Ea7Gsd:
        return tr("DMA Profibus Anleitung §6.1.1–6.1.4: product number ending in 5 uses "
                  "hcs0ea7.gsd, device DMA-22-XX and the 28-byte module; the CMD 15 telegram "
                  "uses the first %1 output and 9 input bytes.");
    case PlcTextId::ProfibusGsd:
        return tr("DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least "
                  "%1 bytes, input at least 9 bytes).");
    case PlcTextId::ProfibusGsdUniversal:
        return tr("DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least "
                  "%1 bytes, input at least 9 bytes) and §5.1.1 (no one-module CMD 15 entry in "
                  "the catalogue: universal module).");
    case PlcTextId::ProfibusGsdAssumed:
        return tr("DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least "
                  "%1 bytes, input at least 9 bytes); product number not given: HCS0220.GSD "
                  "assumed (§6.1.1: numbers ending in 5 use hcs0ea7.gsd).");
    case PlcTextId::ProfibusGsdUniversalAssumed:
        return tr("DMA Profibus Anleitung §1.1 (GSD file), §5.1 (CMD 15 module, output at least "
                  "%1 bytes, input at least 9 bytes) and §5.1.1 (no one-module CMD 15 entry in "
                  "the catalogue: universal module); product number not given: HCS0220.GSD "
                  "assumed (§6.1.1: numbers ending in 5 use hcs0ea7.gsd).");
    case PlcTextId::TadrOut:
        return tr("telegram address, set by the PLC (0 … 255); change it to force an answer");
    case PlcTextId::SnumOpat:
        return tr("number of CAN slaves = %1 (the master, SADR 0, is always included)");
    case PlcTextId::SnumDma: return tr("number of modules = %1");
    case PlcTextId::CmdOut: return tr("command 15 (0x0F)");
    case PlcTextId::ControlByte: return tr("control byte (special functions, bits below)");
    case PlcTextId::ValueHigh: return tr("%1 high byte: %2");
    case PlcTextId::ValueLow: return tr("%1 low byte: %2");
    case PlcTextId::ValueHighParameter: return tr("%1 high byte: %2 %3");
    case PlcTextId::ValueLowParameter: return tr("%1 low byte: %2 %3");
    case PlcTextId::TadrIn: return tr("telegram address, echoed");
    case PlcTextId::SadrIn:
        return tr("address of the module that answered (%1, changes with every answer)");
    case PlcTextId::CmdIn: return tr("command 15 (0x8F = error, byte 3 = exception)");
    case PlcTextId::StatusHigh: return tr("status word high byte: HW_ENABLE, ERROR, BUS_DISABLE");
    case PlcTextId::StatusLow:
        return tr("status word low byte: signals, or the error number while ERROR is set");
    case PlcTextId::AnswerHigh:
        return tr("%1 high byte of the module named by SADR (meaning listed per module)");
    case PlcTextId::AnswerLow:
        return tr("%1 low byte of the module named by SADR (meaning listed per module)");
    }
    return {};
}

} // namespace

QString plcText(const PlcText &text, dev::Language lang)
{
    QString s = PlcConfigText::source(text.id);
    for (const dev::LocalText &arg : text.args)
        s = s.arg(QString::fromStdString(arg.in(lang)));
    return s;
}

} // namespace vt::model
