#include "test_signal.h"

#include "core/key_lookup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace vt::model {

namespace {

constexpr std::array kKinds{SignalKind::Step, SignalKind::Square, SignalKind::Triangle,
                            SignalKind::Sine, SignalKind::Sweep};
constexpr std::array kDirections{StepDirection::Up, StepDirection::Down, StepDirection::Both};

// Bounds that keep a signal something a person meant: an hour at most, a sweep of at most a few
// hundred points.
constexpr double kMaxDuration = 3600;
constexpr int kMaxRepeats = 1000;
constexpr int kMaxCycles = 10'000;
constexpr int kMaxPointsPerDecade = 50;

bool fail(std::string *why, const char *text)
{
    if (why)
        *why = text;
    return false;
}

bool valid(const SignalSpec &s, std::string *why)
{
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(s.from) || !finite(s.to) || !finite(s.hold) || !finite(s.amplitude) ||
        !finite(s.offset) || !finite(s.frequencyHz) || !finite(s.fromHz) || !finite(s.toHz))
        return fail(why, "every number must be finite");
    switch (s.kind) {
    case SignalKind::Step:
        if (s.from == s.to)
            return fail(why, "a step needs different from and to values");
        if (!(s.hold > 0))
            return fail(why, "the hold time must be more than 0 s");
        if (s.repeats < 1 || s.repeats > kMaxRepeats)
            return fail(why, "repeats must be 1..1000");
        return true;
    case SignalKind::Square:
    case SignalKind::Triangle:
    case SignalKind::Sine:
        if (!(s.amplitude > 0))
            return fail(why, "the amplitude must be more than 0");
        if (!(s.frequencyHz > 0))
            return fail(why, "the frequency must be more than 0 Hz");
        if (s.cycles < 1 || s.cycles > kMaxCycles)
            return fail(why, "cycles must be 1..10000");
        if (s.settlingCycles < 0 || s.settlingCycles > kMaxCycles)
            return fail(why, "settling cycles must be 0..10000");
        return true;
    case SignalKind::Sweep:
        if (!(s.amplitude > 0))
            return fail(why, "the amplitude must be more than 0");
        if (!(s.fromHz > 0) || !(s.toHz > s.fromHz))
            return fail(why, "a sweep needs 0 < from frequency < to frequency");
        if (s.pointsPerDecade < 1 || s.pointsPerDecade > kMaxPointsPerDecade)
            return fail(why, "points per decade must be 1..50");
        if (s.cycles < 1 || s.cycles > kMaxCycles)
            return fail(why, "cycles must be 1..10000");
        if (s.settlingCycles < 0 || s.settlingCycles > kMaxCycles)
            return fail(why, "settling cycles must be 0..10000");
        return true;
    }
    return fail(why, "unknown signal");
}

} // namespace

const char *key(SignalKind kind)
{
    switch (kind) {
    case SignalKind::Step: return "step";
    case SignalKind::Square: return "square";
    case SignalKind::Triangle: return "triangle";
    case SignalKind::Sine: return "sine";
    case SignalKind::Sweep: return "sweep";
    }
    return "?";
}

const char *key(StepDirection direction)
{
    switch (direction) {
    case StepDirection::Up: return "up";
    case StepDirection::Down: return "down";
    case StepDirection::Both: return "both";
    }
    return "?";
}

std::vector<double> sweepFrequencies(double fromHz, double toHz, int pointsPerDecade)
{
    std::vector<double> out;
    if (!(fromHz > 0) || !(toHz >= fromHz) || pointsPerDecade < 1)
        return out;
    const double decades = std::log10(toHz / fromHz);
    const int steps = std::max(1, static_cast<int>(std::ceil(decades * pointsPerDecade - 1e-9)));
    for (int i = 0; i <= steps; ++i)
        out.push_back(fromHz * std::pow(toHz / fromHz, static_cast<double>(i) / steps));
    out.back() = toHz;
    return out;
}

std::optional<TestSignal> TestSignal::make(const SignalSpec &spec, std::string *why)
{
    if (!valid(spec, why))
        return std::nullopt;
    TestSignal signal(spec);
    signal.build();
    if (!(signal.m_duration <= kMaxDuration)) {
        fail(why, "the signal would last more than an hour");
        return std::nullopt;
    }
    return signal;
}

void TestSignal::build()
{
    const SignalSpec &s = m_spec;
    switch (s.kind) {
    case SignalKind::Step: {
        const double first = s.direction == StepDirection::Down ? s.to : s.from;
        const double second = s.direction == StepDirection::Down ? s.from : s.to;
        m_levels.push_back(first);
        for (int r = 0; r < s.repeats; ++r) {
            if (r > 0 && s.direction != StepDirection::Both)
                m_levels.push_back(first);
            m_levels.push_back(second);
            if (s.direction == StepDirection::Both)
                m_levels.push_back(first);
        }
        // Up measures the from → to edges, down the to → from ones, both every edge; the way
        // back between repeats is only there to start the next edge from the same level.
        for (std::size_t i = 1; i < m_levels.size(); ++i) {
            if (s.direction == StepDirection::Both || m_levels[i - 1] == first)
                m_edges.push_back({static_cast<double>(i) * s.hold, m_levels[i - 1], m_levels[i],
                                   static_cast<double>(i + 1) * s.hold});
        }
        for (std::size_t i = 1; i < m_levels.size(); ++i)
            m_jumps.push_back(static_cast<double>(i) * s.hold);
        m_duration = static_cast<double>(m_levels.size()) * s.hold;
        m_min = std::min(s.from, s.to);
        m_max = std::max(s.from, s.to);
        return;
    }
    case SignalKind::Square:
    case SignalKind::Triangle:
    case SignalKind::Sine: {
        const double period = 1.0 / s.frequencyHz;
        const int total = s.settlingCycles + s.cycles;
        m_duration = total * period;
        m_min = s.offset - s.amplitude;
        m_max = s.offset + s.amplitude;
        if (s.kind == SignalKind::Square) {
            for (int half = 1; half < 2 * total; ++half) {
                const double t = half * period / 2;
                const bool high = half % 2 == 0;
                m_edges.push_back({t, high ? m_min : m_max, high ? m_max : m_min, t + period / 2});
                m_jumps.push_back(t);
            }
        }
        m_points.push_back({s.frequencyHz, 0, s.settlingCycles * period, s.cycles});
        return;
    }
    case SignalKind::Sweep: {
        double t = 0;
        for (double f : sweepFrequencies(s.fromHz, s.toHz, s.pointsPerDecade)) {
            const double period = 1.0 / f;
            m_points.push_back({f, t, t + s.settlingCycles * period, s.cycles});
            t += (s.settlingCycles + s.cycles) * period;
        }
        m_duration = t;
        m_min = s.offset - s.amplitude;
        m_max = s.offset + s.amplitude;
        return;
    }
    }
}

double TestSignal::periodicAt(double t, double frequencyHz, double phaseStart) const
{
    const SignalSpec &s = m_spec;
    const double cycles = (t - phaseStart) * frequencyHz;
    const double phase = cycles - std::floor(cycles); // 0..1
    switch (s.kind) {
    case SignalKind::Square: return phase < 0.5 ? s.offset + s.amplitude : s.offset - s.amplitude;
    case SignalKind::Triangle: {
        // From the offset up: 0 → +1 over the first quarter, down to −1 at three quarters.
        const double shape = phase < 0.25   ? 4 * phase
                             : phase < 0.75 ? 2 - 4 * phase
                                            : 4 * phase - 4;
        return s.offset + s.amplitude * shape;
    }
    default: return s.offset + s.amplitude * std::sin(2 * std::numbers::pi * phase);
    }
}

double TestSignal::valueAt(double t) const
{
    const SignalSpec &s = m_spec;
    t = std::clamp(t, 0.0, m_duration);
    switch (s.kind) {
    case SignalKind::Step: {
        const auto i = std::min(m_levels.size() - 1, static_cast<std::size_t>(t / s.hold));
        return m_levels[i];
    }
    case SignalKind::Square:
    case SignalKind::Triangle:
    case SignalKind::Sine:
        if (t >= m_duration) // a whole number of cycles ends where it began
            return s.kind == SignalKind::Square ? s.offset - s.amplitude : s.offset;
        return periodicAt(t, s.frequencyHz, 0);
    case SignalKind::Sweep: {
        if (t >= m_duration)
            return s.offset;
        const auto it =
            std::upper_bound(m_points.begin(), m_points.end(), t,
                             [](double v, const SignalPoint &p) { return v < p.start; });
        const SignalPoint &p = *std::prev(it);
        return periodicAt(t, p.frequencyHz, p.start);
    }
    }
    return s.offset;
}

} // namespace vt::model

namespace vt::dev {

template<> std::optional<model::SignalKind> fromKey<model::SignalKind>(std::string_view text)
{
    return keyLookup<model::SignalKind>(model::kKinds, text);
}

template<> std::optional<model::StepDirection> fromKey<model::StepDirection>(std::string_view text)
{
    return keyLookup<model::StepDirection>(model::kDirections, text);
}

} // namespace vt::dev
