// FaultSpec: what FaultLink injects, and its text form for the CLI's --fault option:
//   "drop=0.02,corrupt=0.005,delay=5,cut=120,seed=7"
// A key applies to both directions; "tx." (master → device, send()) or "rx." (device → master,
// received()) limits it to one: "rx.drop=0.1,tx.delay=20". Keys: drop and corrupt (probability
// per frame, 0..1), delay (ms, 0..60000), cut (frames, counted over both directions, after which
// the link goes Failed once), seed (the std::mt19937 seed; default 1). A plain value; any thread.
#pragma once

#include <QString>
#include <QStringView>
#include <core/result.h>
#include <cstdint>
#include <optional>

namespace vt::link {

struct FaultRates
{
    double drop = 0.0;    // probability that a frame vanishes
    double corrupt = 0.0; // probability that one byte of a frame is changed
    int delayMs = 0;      // every frame is held back this long (order is kept)

    bool isNull() const { return drop == 0.0 && corrupt == 0.0 && delayMs == 0; }
    friend bool operator==(const FaultRates &, const FaultRates &) = default;
};

struct FaultSpec
{
    static constexpr std::uint32_t kDefaultSeed = 1;
    static constexpr int kMaxDelayMs = 60'000;

    FaultRates tx; // master → device
    FaultRates rx; // device → master
    std::optional<std::uint64_t> cutAfterFrames;
    std::uint32_t seed = kDefaultSeed;

    bool isNull() const { return tx.isNull() && rx.isNull() && !cutAfterFrames; }
    // Canonical text that parseFaultSpec() reads back to an equal spec.
    QString toString() const;

    friend bool operator==(const FaultSpec &, const FaultSpec &) = default;
};

struct FaultSpecError
{
    QString item;    // the offending "key=value" as written
    QString message; // why it is wrong

    // "fault spec item 'drop=2': probability must be between 0 and 1"
    QString text() const;
};

// An empty (or blank) text is a spec that injects nothing.
dev::Result<FaultSpec, FaultSpecError> parseFaultSpec(QStringView text);

} // namespace vt::link
