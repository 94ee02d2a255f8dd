#include "exceptions.h"

#include <array>
#include <string>

namespace vt::dev::hcs {
namespace {

// German wording from the DMA Profibus Anleitung §3.3 / §4.3 where it has one; its CMD 6 table
// repeats the CMD 3 texts ("CNT == 0 …", "Lesen der ID …"), so codes 3/4 of CMD 6 and CMD 15
// follow the English tables (DMA Profinet manual §3.6) instead.
const LocalText kCommandNotSupported{"command not supported", "Befehl nicht unterstützt"};
const LocalText kWrongId{"wrong ID", "Falsche ID"};
const LocalText kBadCount{"CNT == 0 or CNT > 16 (0x10)", "CNT == 0 oder CNT > 16 (0x10)"};
const LocalText kReadFailed{"reading of ID failed", "Lesen der ID fehlgeschlagen"};
const LocalText kWrongData{"wrong data value", "Falscher Datenwert"};
const LocalText kWriteFailed{"writing of ID failed", "Schreiben der ID fehlgeschlagen"};
const LocalText kTimeoutOrCount{
    "timeout slave, address wrong or not installed, or invalid number of connected slaves",
    "Timeout Slave, Adresse falsch oder nicht installiert oder falsche Anzahl angeschlossener "
    "Slaves (Module)"};
const LocalText kChecksumModbus{"internal checksum error (Modbus)",
                                "Interner Checksum Fehler (Modbus)"};
const LocalText kChecksumCan{"internal checksum error (CAN connection)",
                             "Interner Checksum Fehler (CAN-Verbindung)"};
const LocalText kTimeoutModbus{"timeout (Modbus)", "Timeout (Modbus)"};
const LocalText kTimeoutCan{"timeout (CAN connection)", "Timeout (CAN-Verbindung)"};
const LocalText kInvalidSlaveCount{"invalid number of connected slaves",
                                   "Ungültige Anzahl angeschlossener Slaves"};
const LocalText kTimeoutSlave{"timeout slave, address wrong or not installed",
                              "Timeout Slave, Adresse falsch oder nicht installiert"};
const LocalText kOpatBufferSmall{"telegram too short, Profibus output buffer too small",
                                 "Telegramm zu kurz, Profibus-Ausgangspuffer zu klein"};
const LocalText kNoCanBuffer{"no CAN buffer defined, CAN baud rate not defined",
                             "Kein CAN-Puffer definiert, CAN-Baudrate nicht definiert"};
const LocalText kSlaveErrorByte{"slave sends error byte, command byte unknown",
                                "Slave sendet Fehlerbyte, Befehlsbyte unbekannt"};
const LocalText kDuplicateAddress{"two or more slaves have the same slave address",
                                  "Zwei oder mehr Slaves haben dieselbe Slave-Adresse"};
// DMA Profinet manual §4.3 / DMA Profibus Anleitung §4.3, code 9.
const LocalText kDmaBufferSmall{
    "Profibus node (SADR = 0) reports its receive data buffer too small: the data length of the "
    "selected GSD module is too small",
    "Profibus-Knoten (SADR = 0) schickt „Empfangs-Datenpuffer zu klein“: die definierte Datenlänge "
    "des GSD-Moduls ist zu gering gewählt"};

using Table = std::array<const LocalText *, 12>; // index = code - 1; nullptr = not listed

// OPAT manual §2.3 (CMD 3).
const Table kOpatRead{&kCommandNotSupported, &kWrongId,        &kBadCount,
                      &kReadFailed,          &kTimeoutOrCount, &kChecksumCan,
                      &kInvalidSlaveCount,   &kTimeoutSlave,   &kOpatBufferSmall,
                      &kNoCanBuffer,         &kSlaveErrorByte, &kDuplicateAddress};
// OPAT manual §2.6 (CMD 6).
const Table kOpatWrite{&kCommandNotSupported, &kWrongId,        &kWrongData,
                       &kWriteFailed,         &kTimeoutOrCount, &kChecksumCan,
                       &kInvalidSlaveCount,   &kTimeoutSlave,   &kOpatBufferSmall,
                       &kNoCanBuffer,         &kSlaveErrorByte, &kDuplicateAddress};
// OPAT manual §3.3 (CMD 15): 5 and 6 differ from the CMD 3/6 tables.
const Table kOpatCyclic{&kCommandNotSupported, &kWrongId,        &kWrongData,
                        &kWriteFailed,         &kTimeoutCan,     &kChecksumModbus,
                        &kInvalidSlaveCount,   &kTimeoutSlave,   &kOpatBufferSmall,
                        &kNoCanBuffer,         &kSlaveErrorByte, &kDuplicateAddress};
// DMA Profinet manual §3.3 / DMA Profibus Anleitung §3.3 (CMD 3).
const Table kDmaRead{&kCommandNotSupported,
                     &kWrongId,
                     &kBadCount,
                     &kReadFailed,
                     &kTimeoutOrCount,
                     &kChecksumModbus,
                     nullptr,
                     nullptr,
                     nullptr,
                     nullptr,
                     nullptr,
                     nullptr};
// DMA Profinet manual §3.6 (CMD 6).
const Table kDmaWrite{&kCommandNotSupported,
                      &kWrongId,
                      &kWrongData,
                      &kWriteFailed,
                      &kTimeoutOrCount,
                      &kChecksumModbus,
                      nullptr,
                      nullptr,
                      nullptr,
                      nullptr,
                      nullptr,
                      nullptr};
// DMA Profinet manual §4.3 / DMA Profibus Anleitung §4.3 (CMD 15).
const Table kDmaCyclic{&kCommandNotSupported,
                       &kWrongId,
                       &kWrongData,
                       &kWriteFailed,
                       &kTimeoutModbus,
                       &kChecksumModbus,
                       &kInvalidSlaveCount,
                       &kTimeoutSlave,
                       &kDmaBufferSmall,
                       nullptr,
                       nullptr,
                       nullptr};

const Table *tableFor(Family family, std::uint8_t command)
{
    const bool opat = family == Family::Opat;
    switch (command) {
    case kCmdRead: return opat ? &kOpatRead : &kDmaRead;
    case kCmdWrite: return opat ? &kOpatWrite : &kDmaWrite;
    case kCmdCyclic: return opat ? &kOpatCyclic : &kDmaCyclic;
    default: return nullptr;
    }
}

} // namespace

std::optional<LocalText> exceptionText(Family family, std::uint8_t command, std::uint8_t code)
{
    const Table *table = tableFor(family, command);
    if (table == nullptr || code < 1 || code > table->size())
        return std::nullopt;
    const LocalText *text = (*table)[static_cast<std::size_t>(code - 1)];
    if (text == nullptr)
        return std::nullopt;
    return *text;
}

LocalText exceptionTextOrUnknown(Family family, std::uint8_t command, std::uint8_t code)
{
    if (auto text = exceptionText(family, command, code))
        return *text;
    const std::string n = std::to_string(code);
    return {"unknown exception " + n, "unbekannte Ausnahme " + n};
}

std::uint8_t maxExceptionCode(Family family, std::uint8_t command)
{
    const Table *table = tableFor(family, command);
    if (table == nullptr)
        return 0;
    std::uint8_t last = 0;
    for (std::size_t i = 0; i < table->size(); ++i)
        if ((*table)[i] != nullptr)
            last = static_cast<std::uint8_t>(i + 1);
    return last;
}

} // namespace vt::dev::hcs
