// Result<T>: a value or a typed error, so no exception ever crosses the devices/ boundary.
// C++20 has no std::expected; this is the small subset the codecs need.
#pragma once

#include <cassert>
#include <utility>
#include <variant>

namespace vt::dev {

template<typename T, typename E> class [[nodiscard]] Result
{
public:
    Result(T value) : m_data(std::in_place_index<0>, std::move(value)) {}
    Result(E error) : m_data(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_data.index() == 0; }
    explicit operator bool() const { return ok(); }

    const T &value() const &
    {
        assert(ok());
        return std::get<0>(m_data);
    }
    T &value() &
    {
        assert(ok());
        return std::get<0>(m_data);
    }
    T &&value() &&
    {
        assert(ok());
        return std::get<0>(std::move(m_data));
    }
    const T &operator*() const & { return value(); }
    const T *operator->() const { return &value(); }
    T *operator->() { return &value(); }

    const E &error() const
    {
        assert(!ok());
        return std::get<1>(m_data);
    }

    T valueOr(T fallback) const { return ok() ? std::get<0>(m_data) : std::move(fallback); }

private:
    std::variant<T, E> m_data;
};

} // namespace vt::dev
