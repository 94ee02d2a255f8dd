// Synthetic recordings with known answers for the tuning analysis tests: polled sample times
// (uneven, deterministic), analytic step responses, and a first-order lag driven exactly by a
// staircase set value.
#pragma once

#include "model/tuning/samples.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

namespace vt::model::test {

// Deterministic values in [−1, 1]: a seeded mt19937, whose sequence the standard fixes.
class FixedNoise
{
public:
    explicit FixedNoise(std::uint32_t seed) : m_gen(seed) {}
    double next() { return static_cast<double>(m_gen()) / 4294967295.0 * 2.0 - 1.0; }

private:
    std::mt19937 m_gen;
};

// Times from `from` to `to` at `rateHz`, each but the first moved by up to ±jitter/2 of an
// interval (jitter < 1 keeps them ascending), as a monitor polling channels in turn gets them.
inline std::vector<double> polledTimes(double from, double to, double rateHz, double jitter,
                                       std::uint32_t seed)
{
    FixedNoise noise(seed);
    std::vector<double> t{from};
    const double dt = 1.0 / rateHz;
    for (std::size_t i = 1;; ++i) {
        const double nominal = from + static_cast<double>(i) * dt;
        if (nominal > to)
            break;
        t.push_back(std::min(to, nominal + 0.5 * jitter * dt * noise.next()));
    }
    return t;
}

inline Samples sampled(const std::vector<double> &times, const std::function<double(double)> &f)
{
    Samples s;
    s.t = times;
    for (double t : times)
        s.y.push_back(f(t));
    return s;
}

// Normalised step responses s(t) (0 before the step, 1 when settled), t from the step.
inline std::function<double(double)> firstOrder(double tau)
{
    return [tau](double t) { return t <= 0 ? 0.0 : 1.0 - std::exp(-t / tau); };
}

inline std::function<double(double)> secondOrder(double zeta, double omegaN)
{
    return [zeta, omegaN](double t) {
        if (t <= 0)
            return 0.0;
        const double root = std::sqrt(1.0 - zeta * zeta);
        const double wd = omegaN * root;
        return 1.0 -
               std::exp(-zeta * omegaN * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t));
    };
}

// The actual value of a step from `from` to `to` at stepTime through a transport delay and s.
inline std::function<double(double)> stepThrough(double from, double to, double stepTime,
                                                 double delay, std::function<double(double)> s)
{
    return [=](double t) { return from + (to - from) * s(t - stepTime - delay); };
}

// The exact response of a first-order lag (gain 1, time constant tau, at rest on the first set
// value) to the set value read as a staircase, at `times`.
inline Samples lagResponse(const Samples &setValue, double tau, const std::vector<double> &times)
{
    Samples out;
    out.t = times;
    std::size_t next = 1;
    double x = setValue.y.front();
    double u = setValue.y.front();
    double since = setValue.t.front();
    for (double t : times) {
        for (; next < setValue.t.size() && setValue.t[next] <= t; ++next) {
            x = u + (x - u) * std::exp(-(setValue.t[next] - since) / tau);
            since = setValue.t[next];
            u = setValue.y[next];
        }
        out.y.push_back(t <= since ? x : u + (x - u) * std::exp(-(t - since) / tau));
    }
    return out;
}

// One point of a stepped-sine sweep: `settle` cycles to let the loop settle, then `cycles` to
// measure, from `start`.
struct SweepPoint
{
    double frequencyHz = 0;
    int settle = 0;
    int cycles = 0;
    double start = 0;
    double measureFrom() const { return start + settle / frequencyHz; }
    double end() const { return start + (settle + cycles) / frequencyHz; }
};

// A sweep written point after point from t = 0 at `updateHz` (confirmed at polled times):
// offset + amplitude · sin(2πf(t − start)) per point, then the offset.
inline Samples sweepSetValue(std::vector<SweepPoint> &points, double offset, double amplitude,
                             double updateHz, std::uint32_t seed)
{
    double start = 0;
    for (SweepPoint &p : points) {
        p.start = start;
        start = p.end();
    }
    Samples u;
    u.t = polledTimes(0, start + 1.0, updateHz, 0.4, seed);
    std::size_t k = 0;
    for (double t : u.t) {
        while (k < points.size() && t >= points[k].end())
            ++k;
        u.y.push_back(k < points.size() ? offset + amplitude * std::sin(2.0 * std::numbers::pi *
                                                                        points[k].frequencyHz *
                                                                        (t - points[k].start))
                                        : offset);
    }
    return u;
}

} // namespace vt::model::test
