// forEachSegment: the (at most two) contiguous pieces of a ring's rows, for SampleStore's loops.
// Internal to model/monitor (sample_store*.cpp).
#pragma once

#include <QtGlobal>
#include <algorithm>
#include <cstddef>

namespace vt::model {

// Calls fn(firstPhysical, endPhysical) for the pieces of rows [i0, i1) of a ring of `capacity`
// slots whose row 0 is in slot `head`.
template<typename Fn>
void forEachSegment(std::size_t head, std::size_t capacity, qsizetype i0, qsizetype i1, Fn fn)
{
    if (i0 >= i1)
        return;
    const std::size_t p0 = (head + static_cast<std::size_t>(i0)) % capacity;
    const auto n = static_cast<std::size_t>(i1 - i0);
    const std::size_t first = std::min(n, capacity - p0);
    fn(p0, p0 + first);
    if (first < n)
        fn(std::size_t{0}, n - first);
}

} // namespace vt::model
