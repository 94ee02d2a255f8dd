// The fuzz targets' property check: a broken property traps where libFuzzer reports it, also in
// the RelWithDebInfo fuzz build, where assert() is compiled out.
#pragma once

namespace vt::fuzz {

inline void require(bool condition)
{
    if (!condition)
        __builtin_trap();
}

} // namespace vt::fuzz
