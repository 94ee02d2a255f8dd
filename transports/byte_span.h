// The Qt layers hold bytes in QByteArray, the protocol core reads std::span<const std::uint8_t>
// and writes std::vector<std::uint8_t>: the two views of the same bytes, without copies where
// none is needed. The span lives as long as the QByteArray is neither changed nor destroyed.
#pragma once

#include <QByteArray>
#include <cstdint>
#include <span>

namespace vt::link {

inline std::span<const std::uint8_t> byteSpan(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()),
            static_cast<std::size_t>(bytes.size())};
}

inline QByteArray toByteArray(std::span<const std::uint8_t> bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()),
                      static_cast<qsizetype>(bytes.size()));
}

} // namespace vt::link
