// What does the tuning analysis of a whole recording cost against merely copying it? A 1 h
// recording at 200 Hz (720 000 rows, polled at uneven times) with 5 channels — set value,
// actual value and three others — analysed twice:
//   steps: a step every 10 s (360 steps): findStepEdges, then stepMetrics of every step;
//   sweep: a 30-point stepped-sine sweep, 0.1..8 Hz, 120 s per point (2 settling cycles, the
//          rest measured): frequencyPoint of every point, then the −3 dB and −90° frequencies.
// Baseline, same run and same data: a plain copy of the recording's 5 channels (Samples).
// Median of 5 interleaved runs each, in CPU time of this thread (the machine is shared: CPU time
// keeps other processes out; wall time is printed beside it). Prints the times and
// `RESULT name=value` lines with the ratios (docs/PERFORMANCE.md). Not a Google Benchmark: one
// figure per analysis, like session_bench.
#include "model/tuning/frequency_response.h"
#include "model/tuning/step_metrics.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <time.h>
#include <vector>

namespace {

using namespace vt::model;
using Clock = std::chrono::steady_clock;

struct Times
{
    std::vector<double> cpu, wall; // ms
};

constexpr double kSeconds = 3600;
constexpr double kRateHz = 200;
constexpr double kUpdateHz = 100;
constexpr double kStepEvery = 10; // s
constexpr int kSweepPoints = 30;
constexpr double kPointSeconds = kSeconds / kSweepPoints;
constexpr int kSettleCycles = 2;
constexpr int kRuns = 5;
constexpr double kSweepTau = 0.05; // s, the lag the sweep's actual follows

using Recording = std::array<Samples, 5>; // set value, actual, three other channels

std::vector<double> polledTimes()
{
    std::mt19937 gen(1);
    std::vector<double> t;
    const auto rows = static_cast<std::size_t>(kSeconds * kRateHz);
    t.reserve(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        const double jitter = (static_cast<double>(gen()) / 4294967295.0 - 0.5) * 0.8;
        t.push_back((static_cast<double>(i) + (i == 0 ? 0.0 : jitter)) / kRateHz);
    }
    return t;
}

// The rows of a recording whose set value is written at every other row (kUpdateHz) with
// setAt(t) and whose actual follows it through a first-order lag, plus 0.2 % fixed noise.
Recording record(const std::vector<double> &t, const std::function<double(double)> &setAt,
                 double tau)
{
    Recording r;
    for (Samples &c : r) {
        c.t = t;
        c.y.reserve(t.size());
    }
    std::mt19937 gen(2);
    double written = setAt(0), x = written;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (i > 0)
            x = written + (x - written) * std::exp(-(t[i] - t[i - 1]) / tau);
        if (i % 2 == 0)
            written = setAt(t[i]);
        const double noise = (static_cast<double>(gen()) / 4294967295.0 - 0.5) * 0.04;
        r[0].y.push_back(written);
        r[1].y.push_back(x + noise);
        r[2].y.push_back(std::sin(t[i]));
        r[3].y.push_back(std::cos(0.3 * t[i]));
        r[4].y.push_back(noise);
    }
    return r;
}

double stepLevel(double t)
{
    const auto k = static_cast<std::uint64_t>(t / kStepEvery);
    return 1.0 + static_cast<double>((k * 37) % 9); // 1..9 V, never the same twice in a row
}

double pointHz(int k)
{
    return 0.1 * std::pow(80.0, static_cast<double>(k) / (kSweepPoints - 1)); // 0.1..8 Hz
}

double sweepAt(double t)
{
    const int k = std::min(kSweepPoints - 1, static_cast<int>(t / kPointSeconds));
    const double local = t - k * kPointSeconds;
    return 5.0 + 2.0 * std::sin(2 * std::numbers::pi * pointHz(k) * local);
}

double analyseSteps(const Recording &r)
{
    const std::vector<StepEdge> edges = findStepEdges(r[0], 0.01, r[0].t.back());
    double sum = 0;
    for (const StepEdge &edge : edges) {
        const auto m = stepMetrics(r[1], edge);
        sum += m.ok() ? m->riseTime + m->settlingTime2 : -1e6; // a refusal shows in the sum
    }
    return sum + static_cast<double>(edges.size());
}

std::vector<FrequencyPoint> sweepPoints(const Recording &r)
{
    const FrequencyLimits limits{averageRateHz(r[1]), kUpdateHz};
    std::vector<FrequencyPoint> points;
    for (int k = 0; k < kSweepPoints; ++k) {
        const double f = pointHz(k);
        // The whole cycles after the settling ones that end before the point does.
        const int cycles = static_cast<int>(std::floor(f * kPointSeconds)) - kSettleCycles - 1;
        const double t0 = k * kPointSeconds + kSettleCycles / f;
        points.push_back(frequencyPoint(r[0], r[1], f, t0, cycles, limits));
    }
    return points;
}

double analyseSweep(const Recording &r)
{
    const std::vector<FrequencyPoint> points = sweepPoints(r);
    return gainCrossing(points).value_or(-1e6) + phaseCrossing(points).value_or(-1e6);
}

double copy(const Recording &r)
{
    const Recording copied = r;
    return copied[1].y[copied[1].y.size() / 2];
}

double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

void measure(Times &times, volatile double &sink, const std::function<double()> &work)
{
    const double cpu = threadCpuMs();
    const auto start = Clock::now();
    sink = sink + work();
    times.wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    times.cpu.push_back(threadCpuMs() - cpu);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main()
{
    const std::vector<double> t = polledTimes();
    const Recording steps = record(t, stepLevel, 0.2);
    const Recording sweep = record(t, sweepAt, kSweepTau);
    volatile double sink = 0;
    Times copySteps, stepTimes, copySweep, sweepTimes;
    for (int run = 0; run < kRuns; ++run) { // interleaved, so load changes hit all alike
        measure(copySteps, sink, [&] { return copy(steps); });
        measure(stepTimes, sink, [&] { return analyseSteps(steps); });
        measure(copySweep, sink, [&] { return copy(sweep); });
        measure(sweepTimes, sink, [&] { return analyseSweep(sweep); });
    }
    // What the timed runs computed, so a bench that measures refusals shows it.
    const std::vector<StepEdge> edges = findStepEdges(steps[0], 0.01, t.back());
    std::size_t measured = 0;
    for (const StepEdge &edge : edges)
        if (stepMetrics(steps[1], edge).ok())
            ++measured;
    const std::vector<FrequencyPoint> points = sweepPoints(sweep);
    const auto valid = static_cast<std::size_t>(std::count_if(
        points.begin(), points.end(), [](const FrequencyPoint &p) { return p.valid; }));
    const double f3 = gainCrossing(points).value_or(0);

    const double cSteps = median(copySteps.cpu), aSteps = median(stepTimes.cpu);
    const double cSweep = median(copySweep.cpu), aSweep = median(sweepTimes.cpu);
    std::printf("tuning analysis of %zu rows x 5 channels (1 h at 200 Hz), median of %d runs, "
                "CPU (wall) ms\n",
                t.size(), kRuns);
    std::printf("  copy of the step recording:  %8.2f (%8.2f)\n", cSteps, median(copySteps.wall));
    std::printf("  step metrics:                %8.2f (%8.2f)  %zu of %zu steps measured\n", aSteps,
                median(stepTimes.wall), measured, edges.size());
    std::printf("  copy of the sweep recording: %8.2f (%8.2f)\n", cSweep, median(copySweep.wall));
    std::printf("  sweep:                       %8.2f (%8.2f)  %zu of %d points valid, "
                "-3 dB at %.2f Hz (the lag's: %.2f Hz)\n",
                aSweep, median(sweepTimes.wall), valid, kSweepPoints, f3,
                1 / (2 * std::numbers::pi * kSweepTau));
    std::printf("RESULT step_metrics_720k_vs_copy_ratio=%.3f\n", aSteps / cSteps);
    std::printf("RESULT sweep_720k_vs_copy_ratio=%.3f\n", aSweep / cSweep);
    std::printf("RESULT analysis_720k_vs_copy_ratio=%.3f\n", (aSteps + aSweep) / (cSteps + cSweep));
    return measured == edges.size() && !edges.empty() && valid == points.size() ? 0 : 1;
}
