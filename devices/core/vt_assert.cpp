#include "core/vt_assert.h"

#include <atomic>
#include <cstdio>

namespace vt {
namespace {

void toStderr(const char *condition, const char *file, int line)
{
    std::fprintf(stderr, "ASSERTION \"%s\" FAILED at %s:%d\n", condition, file, line);
}

std::atomic<AssertHandler> g_handler{&toStderr};

} // namespace

AssertHandler setAssertHandler(AssertHandler handler)
{
    return g_handler.exchange(handler ? handler : &toStderr);
}

void assertFailed(const char *condition, const char *file, int line)
{
    g_handler.load()(condition, file, line);
}

} // namespace vt
