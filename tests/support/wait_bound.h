// The one bound of every wait in the tests: how long something that must happen may take before
// the test fails. A passing test never waits for it; a check that something does NOT happen names
// its own short window instead. Qt-free, for the process tests too.
#pragma once

namespace vt::test {

inline constexpr int kWaitMs = 30'000;

} // namespace vt::test
