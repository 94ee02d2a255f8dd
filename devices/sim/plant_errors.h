// Errors the simulated plant detects, as a bit set, and the error numbers the modules report
// for them (module state low byte / ERR): DMA Profinet manual §4.5.1.1 and DMA Profibus
// Anleitung §4.5.1.1 "Fehlernummern"; OPAT manual §7 ID 0x102 ERR.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace vt::dev {
struct Dictionary;
}

namespace vt::dev::sim {

enum class PlantError : std::uint8_t {
    SetValueWireBreak,      // current set value input S1.06 below 2 mA (E15 "with cable fracture
                            // detection")
    SetValueWireBreak2,     // same at S1.05 (E16), DMA only
    SetValueOverCurrent,    // S1.06 above 25 mA (with detection)
    SetValueOverCurrent2,   // S1.05 above 25 mA
    FeedbackCableFracture,  // feedback sensor signal below its live zero while C1.26 is on
    FeedbackOverload,       // current feedback sensor above 22 mA
    OutputShortCircuit,     // output stage peak current above 8 A
    OutputCurrentDeviation, // |desired − actual current| > 250 mA for ~100 ms (open/short circuit,
                            // over current)
    Count
};

// Which manual's numbering applies.
enum class ErrorTable { Dma, Opat };

// OPAT families use the OPAT ERR list, every other HCS family the DMA table.
ErrorTable errorTableFor(const Dictionary &dict);

// The number the module reports, or nothing when the manual has none for this error.
//  DMA: 2 wire break S1.06, 4 wire break S1.05, 5/6 over current S1.06/S1.05, 3 short circuit
//       (peak > 8 A), 8 current deviation. The DMA table has no feedback entry: ASSUMPTION, the
//       feedback errors report 1 "Error of operation".
//  OPAT: 9 wire break on set value, 2/4 wire break sensor 1/2 (branch 1/2), 5/6 overload
//       > 22 mA sensor 1/2, 8 wire break at the output stages (also used for short circuit and
//       current deviation: the OPAT list has no separate entry). No set value over-current entry.
std::optional<int> errorNumber(PlantError error, ErrorTable table, int branch = 1);
const char *errorKey(PlantError error); // "feedback-cable-fracture", for logs and tests

class PlantErrors
{
public:
    void set(PlantError e) { m_bits |= bit(e); }
    void clear(PlantError e) { m_bits &= static_cast<std::uint32_t>(~bit(e)); }
    bool test(PlantError e) const { return (m_bits & bit(e)) != 0; }
    bool any() const { return m_bits != 0; }
    void reset() { m_bits = 0; }
    std::uint32_t bits() const { return m_bits; }
    PlantErrors &operator|=(const PlantErrors &o)
    {
        m_bits |= o.m_bits;
        return *this;
    }
    bool operator==(const PlantErrors &) const = default;

    // The number to report when several errors are pending: the lowest one the table has.
    std::optional<int> reportedNumber(ErrorTable table, int branch = 1) const;
    std::string text() const; // "feedback-cable-fracture, output-short-circuit"

private:
    static std::uint32_t bit(PlantError e) { return 1u << static_cast<unsigned>(e); }
    std::uint32_t m_bits = 0;
};

// The cards latch an error and switch the outputs off until it is acknowledged (hardware enable
// off/on, Bus Disable set/reset, OPAT EClr) after its cause has gone (DMA Profinet manual
// §4.5.1.1: "Generally the electronic discards every set point in error case and the outputs
// will be disabled"; "Mandatory condition for resetting an error is that the failure causing the
// error has been cleared or removed").
class ErrorLatch
{
public:
    // Called every step with the errors whose cause is present now.
    void update(const PlantErrors &present);
    // Clears the latched errors whose cause has gone; returns true when none is left.
    bool acknowledge();
    const PlantErrors &latched() const { return m_latched; }
    const PlantErrors &present() const { return m_present; }
    bool tripped() const { return m_latched.any(); }

private:
    PlantErrors m_present;
    PlantErrors m_latched;
};

} // namespace vt::dev::sim
