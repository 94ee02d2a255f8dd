// VT_ASSERT(cond, action): the house rule for programmer errors (a null that must not be null,
// an index our own code got wrong, an impossible enum value) — log the condition with file and
// line, then recover with `action` (`return {}`, `return`, `continue` …) instead of crashing.
// Not for bad input (frames, files, user text): those are expected and answered as errors.
// The log goes to one replaceable handler: stderr here in the Qt-free core; the Qt layers route
// it to the Qt message log (model/assert_handler.h). Any thread.
#pragma once

namespace vt {

// Called for every failed VT_ASSERT with the condition's text, __FILE__ and __LINE__.
using AssertHandler = void (*)(const char *condition, const char *file, int line);

// Installs `handler` (nullptr: the stderr default) and returns the one it replaces.
AssertHandler setAssertHandler(AssertHandler handler);

// Hands a failed assertion to the current handler (what VT_ASSERT calls).
void assertFailed(const char *condition, const char *file, int line);

} // namespace vt

// The if/else form (as Qt Creator's QTC_ASSERT) keeps `break` and `continue` in `action` bound
// to the caller's loop; the trailing do-while asks for the semicolon.
#define VT_ASSERT(cond, action)                                                                    \
    if (cond) [[likely]] {                                                                         \
    } else {                                                                                       \
        ::vt::assertFailed(#cond, __FILE__, __LINE__);                                             \
        action;                                                                                    \
    }                                                                                              \
    do {                                                                                           \
    } while (false)
