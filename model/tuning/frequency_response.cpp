#include "frequency_response.h"

#include "core/vt_assert.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <numbers>
#include <utility>

namespace vt::model {
namespace {

using Complex = std::complex<double>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ∫ (u(t) − ū) e^{−jωτ} dτ over τ = t − t0 ∈ [0, T] for the staircase u, exactly; nullopt when u
// does not change in the window.
std::optional<Complex> staircaseBin(const Samples &u, double t0, double window, double omega)
{
    const double t1 = t0 + window;
    std::size_t k = firstAfter(u, t0) - 1; // u.t.front() ≤ t0: checked by the caller
    const double ref = u.y[k];
    double level = 0; // u − ref on the current segment
    double lo = 0, hi = 0;
    double a = 0;
    Complex ea = 1.0;
    Complex sum = 0.0; // Σ level · (e^{−jωa} − e^{−jωb}); divided by jω at the end
    double area = 0;   // ∫ (u − ref) dτ
    const auto segment = [&](double b) {
        const Complex eb = std::polar(1.0, -omega * b);
        sum += level * (ea - eb);
        area += level * (b - a);
        a = b;
        ea = eb;
    };
    for (++k; k < u.t.size() && u.t[k] < t1; ++k) {
        segment(u.t[k] - t0);
        level = u.y[k] - ref;
        lo = std::min(lo, level);
        hi = std::max(hi, level);
    }
    segment(window);
    const Complex jw(0.0, omega);
    const double mean = area / window;
    const Complex bin = (sum - mean * (1.0 - ea)) / jw; // ea is e^{−jωT} now
    if (!(hi > lo) || !(2.0 * std::abs(bin) / window > 1e-9 * (hi - lo)))
        return std::nullopt;
    return bin;
}

struct ActualBin
{
    Complex bin;
    double acEnergy = 0; // ∫ (y − ȳ)² dτ
    std::size_t inside = 0;
};

// The trapezoid sum of (y(t) − ȳ) e^{−jωτ} over the samples strictly inside the window and the
// window's ends read by linear interpolation.
ActualBin sampledBin(const Samples &y, double t0, double window, double omega)
{
    const double t1 = t0 + window;
    const double ref = valueAt(y, t0);
    ActualBin out;
    Complex s1 = 0.0, s0 = 0.0; // trapezoid sums of (y − ref)·e and of e
    double a1 = 0, a2 = 0;      // trapezoid sums of (y − ref) and (y − ref)²
    double prevTau = 0, prevV = 0;
    Complex prevE = 1.0;
    const auto step = [&](double tau, double v) {
        const Complex e = std::polar(1.0, -omega * tau);
        const double h = 0.5 * (tau - prevTau);
        s1 += h * (prevV * prevE + v * e);
        s0 += h * (prevE + e);
        a1 += h * (prevV + v);
        a2 += h * (prevV * prevV + v * v);
        prevTau = tau;
        prevV = v;
        prevE = e;
    };
    for (std::size_t i = firstAfter(y, t0); i < y.t.size() && y.t[i] < t1; ++i) {
        step(y.t[i] - t0, y.y[i] - ref);
        ++out.inside;
    }
    step(window, valueAt(y, t1) - ref);
    const double mean = a1 / window;
    out.bin = s1 - mean * s0;
    out.acEnergy = a2 - window * mean * mean;
    return out;
}

double wrapInto360(double deg)
{
    // atan2 gives (−180°, 180°]; a positive angle is read as the lag it equals.
    return deg > 0 ? deg - 360.0 : deg + 0.0;
}

// Valid points in order of frequency: (index into points).
std::vector<std::size_t> validByFrequency(const std::vector<FrequencyPoint> &points)
{
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].valid && points[i].frequencyHz > 0 && std::isfinite(points[i].gainDb) &&
            std::isfinite(points[i].phaseDeg))
            order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a].frequencyHz < points[b].frequencyHz;
    });
    return order;
}

// First fall from ≥ level to < level along (frequency, value) pairs, interpolated on log f.
std::optional<double> firstFall(const std::vector<std::pair<double, double>> &curve, double level)
{
    for (std::size_t i = 1; i < curve.size(); ++i) {
        const auto [fa, va] = curve[i - 1];
        const auto [fb, vb] = curve[i];
        if (va >= level && vb < level) {
            const double w = (va - level) / (va - vb);
            return std::exp(std::log(fa) + w * (std::log(fb) - std::log(fa)));
        }
    }
    return std::nullopt;
}

} // namespace

double maxValidFrequency(const FrequencyLimits &limits)
{
    if (!(limits.sampleRateHz > 0) || !(limits.updateRateHz > 0))
        return 0;
    return std::min(limits.sampleRateHz, limits.updateRateHz) / kMinPerCycle;
}

FrequencyPoint frequencyPoint(const Samples &setValue, const Samples &actual, double frequencyHz,
                              double t0, int cycles, const FrequencyLimits &limits)
{
    FrequencyPoint p;
    p.frequencyHz = frequencyHz;
    p.gainDb = kNaN;
    p.phaseDeg = kNaN;
    VT_ASSERT(setValue.t.size() == setValue.y.size() && actual.t.size() == actual.y.size(), {
        p.problem = FrequencyProblem::BadRequest;
        return p;
    });
    if (!(frequencyHz > 0) || !std::isfinite(frequencyHz) || cycles < 1 || !std::isfinite(t0)) {
        p.problem = FrequencyProblem::BadRequest;
        return p;
    }
    const double window = cycles / frequencyHz;
    if (setValue.t.empty() || actual.t.empty() || setValue.t.front() > t0 ||
        actual.t.front() > t0 || actual.t.back() < t0 + window) {
        p.problem = FrequencyProblem::OutsideRecording;
        return p;
    }
    const double omega = 2.0 * std::numbers::pi * frequencyHz;
    const ActualBin y = sampledBin(actual, t0, window, omega);
    if (y.inside < 2) {
        p.problem = FrequencyProblem::TooFewSamples;
        return p;
    }
    const std::optional<Complex> u = staircaseBin(setValue, t0, window, omega);
    if (!u) {
        p.problem = FrequencyProblem::NoExcitation;
        return p;
    }
    const Complex g = y.bin / *u;
    p.gainDb = 20.0 * std::log10(std::abs(g));
    p.phaseDeg = wrapInto360(std::arg(g) * 180.0 / std::numbers::pi);
    p.quality =
        y.acEnergy > 0 ? std::clamp(2.0 * std::norm(y.bin) / window / y.acEnergy, 0.0, 1.0) : 0.0;
    if (frequencyHz > maxValidFrequency(limits))
        p.problem = FrequencyProblem::AboveValidBand;
    else if (static_cast<double>(y.inside) < 0.5 * kMinPerCycle * cycles)
        p.problem = FrequencyProblem::TooFewSamples;
    p.valid = p.problem == FrequencyProblem::None;
    return p;
}

std::vector<double> unwrappedPhaseDeg(const std::vector<FrequencyPoint> &points)
{
    std::vector<double> out(points.size(), kNaN);
    bool first = true;
    double previous = 0;
    for (std::size_t i : validByFrequency(points)) {
        double deg = points[i].phaseDeg;
        if (first) {
            deg = std::remainder(deg, 360.0); // [−180°, 180°]
            if (deg <= -180.0)
                deg += 360.0;
        } else
            deg += 360.0 * std::round((previous - deg) / 360.0);
        out[i] = previous = deg;
        first = false;
    }
    return out;
}

std::optional<double> gainCrossing(const std::vector<FrequencyPoint> &points, double gainDb)
{
    std::vector<std::pair<double, double>> curve;
    for (std::size_t i : validByFrequency(points))
        curve.emplace_back(points[i].frequencyHz, points[i].gainDb);
    return firstFall(curve, gainDb);
}

std::optional<double> phaseCrossing(const std::vector<FrequencyPoint> &points, double phaseDeg)
{
    const std::vector<double> unwrapped = unwrappedPhaseDeg(points);
    std::vector<std::pair<double, double>> curve;
    for (std::size_t i : validByFrequency(points))
        curve.emplace_back(points[i].frequencyHz, unwrapped[i]);
    return firstFall(curve, phaseDeg);
}

std::string_view frequencyProblemKey(FrequencyProblem problem)
{
    switch (problem) {
    case FrequencyProblem::None: return "none";
    case FrequencyProblem::BadRequest: return "bad-request";
    case FrequencyProblem::OutsideRecording: return "outside-recording";
    case FrequencyProblem::TooFewSamples: return "too-few-samples";
    case FrequencyProblem::NoExcitation: return "no-excitation";
    case FrequencyProblem::AboveValidBand: return "above-valid-band";
    }
    return "none";
}

} // namespace vt::model
