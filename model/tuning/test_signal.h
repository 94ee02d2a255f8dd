// TestSignal: the workbench's excitations — step, square, triangle, sine and stepped-sine sweep —
// as a set value over time, in the set value's display unit (V, mm …), with the parts the
// analysis needs (each step edge, each sweep point's measuring window). Plain C++, no Qt: the
// engine asks valueAt(t) each time it writes, so the signal never depends on how fast the link is.
#pragma once

#include "core/enum_key.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::model {

enum class SignalKind { Step, Square, Triangle, Sine, Sweep };
const char *key(SignalKind kind); // "step", "square", … (dev::fromKey<SignalKind> below)

// up: from → to; down: to → from; both: from → to → from (each repeat).
enum class StepDirection { Up, Down, Both };
const char *key(StepDirection direction); // "up", "down", "both"

struct SignalSpec
{
    SignalKind kind = SignalKind::Step;
    // Step: the set value settles at the first level for `hold` seconds, then each edge is held.
    double from = 0;
    double to = 0;
    double hold = 1;
    int repeats = 1;
    StepDirection direction = StepDirection::Up;
    // Square, triangle, sine: offset ± amplitude at frequencyHz for `cycles` whole cycles.
    // Sweep: the same amplitude and offset, from fromHz to toHz in log steps.
    double amplitude = 0;
    double offset = 0;
    double frequencyHz = 1;
    int cycles = 3;
    double fromHz = 0.5;
    double toHz = 10;
    int pointsPerDecade = 5;
    int settlingCycles = 2; // sweep: cycles at each frequency before the measured ones
};

// One level change of a step signal, in signal time (seconds from the start).
struct SignalEdge
{
    double time = 0;
    double from = 0;
    double to = 0;
    double end = 0; // the level is held until here
};

// One frequency of a sine or sweep: measured over [measureStart, measureStart + cycles / f].
struct SignalPoint
{
    double frequencyHz = 0;
    double start = 0;        // the frequency begins (settling cycles first)
    double measureStart = 0; // after the settling cycles
    int cycles = 0;
};

class TestSignal
{
public:
    // Empty with a reason when the spec cannot make a signal (zero amplitude, from == to, a
    // frequency out of order …): the text is English, for the caller to translate by key.
    static std::optional<TestSignal> make(const SignalSpec &spec, std::string *why = nullptr);

    const SignalSpec &spec() const { return m_spec; }
    double duration() const { return m_duration; }
    // The set value at `t` seconds from the start; before 0 the first value, after the end the
    // last one.
    double valueAt(double t) const;
    double minimum() const { return m_min; }
    double maximum() const { return m_max; }
    // The value the signal starts with (written before the clock starts).
    double initialValue() const { return valueAt(0); }

    const std::vector<SignalEdge> &edges() const { return m_edges; } // step and square
    // Every time the value jumps (step and square, the unmeasured way back included); empty
    // for the continuous signals.
    const std::vector<double> &jumps() const { return m_jumps; }
    const std::vector<SignalPoint> &points() const { return m_points; } // sine and sweep

private:
    explicit TestSignal(SignalSpec spec) : m_spec(spec) {}
    void build();
    double periodicAt(double t, double frequencyHz, double phaseStart) const;

    SignalSpec m_spec;
    double m_duration = 0;
    double m_min = 0;
    double m_max = 0;
    std::vector<SignalEdge> m_edges;
    std::vector<SignalPoint> m_points;
    std::vector<double> m_jumps;
    std::vector<double> m_levels; // step: level of each hold, m_levels[i] over [i·hold, (i+1)·hold)
};

// The frequencies of a stepped-sine sweep: pointsPerDecade per decade from fromHz, ending at
// toHz exactly.
std::vector<double> sweepFrequencies(double fromHz, double toHz, int pointsPerDecade);

} // namespace vt::model

namespace vt::dev {
template<> std::optional<model::SignalKind> fromKey<model::SignalKind>(std::string_view text);
template<> std::optional<model::StepDirection> fromKey<model::StepDirection>(std::string_view text);
} // namespace vt::dev
