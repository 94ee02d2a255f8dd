#include "deframer.h"

#include "rtu.h"
#include "tcp.h"

#include <iterator>

namespace vt::dev::modbus {

std::vector<Bytes> RtuDeframer::feed(std::span<const std::uint8_t> bytes)
{
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::vector<Bytes> frames;
    while (!m_buffer.empty()) {
        const std::span<const std::uint8_t> buf(m_buffer);
        const auto length = rtuFrameLength(buf, m_direction);
        if (!length) { // no frame of ours starts here
            drop(1, true);
            continue;
        }
        if (*length == 0 || *length > buf.size()) {
            // Waiting for more bytes — unless garbage at the front announced a long frame and a
            // valid frame has meanwhile arrived behind it.
            if (auto at = laterFrame()) {
                drop(*at, true);
                continue;
            }
            m_checked = m_buffer.size();
            break;
        }
        if (rtuCrcOk(buf.first(*length))) {
            frames.emplace_back(m_buffer.begin(),
                                m_buffer.begin() + static_cast<std::ptrdiff_t>(*length));
            drop(*length, false);
        } else {
            drop(1, true); // a corrupt frame or noise: resynchronise one byte further
        }
    }
    return frames;
}

// The first offset > 0 where a complete CRC-valid frame starts. Only candidates that end beyond
// m_checked are new: older ones were rejected before, which keeps each candidate to one CRC
// check and the chance of a false match (1 in 65536 per check) negligible.
std::optional<std::size_t> RtuDeframer::laterFrame() const
{
    const std::span<const std::uint8_t> buf(m_buffer);
    for (std::size_t i = 1; i + 4 < buf.size(); ++i) {
        const auto length = rtuFrameLength(buf.subspan(i), m_direction);
        if (!length || *length == 0)
            continue;
        const std::size_t end = i + *length;
        if (end > buf.size() || end <= m_checked)
            continue;
        if (rtuCrcOk(buf.subspan(i, *length)))
            return i;
    }
    return std::nullopt;
}

void RtuDeframer::drop(std::size_t n, bool garbage)
{
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(n));
    m_checked = m_checked > n ? m_checked - n : 0;
    if (garbage)
        m_discarded += n;
}

void RtuDeframer::silence()
{
    m_discarded += m_buffer.size();
    m_buffer.clear();
    m_checked = 0;
}

std::vector<Bytes> TcpDeframer::feed(std::span<const std::uint8_t> bytes)
{
    std::vector<Bytes> frames;
    if (m_error)
        return frames;
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::size_t at = 0;
    while (m_buffer.size() - at >= kMbapSize) {
        const std::span<const std::uint8_t> rest =
            std::span<const std::uint8_t>(m_buffer).subspan(at);
        auto header = decodeMbap(rest);
        if (!header.ok()) {
            m_error = header.error();
            break;
        }
        const std::size_t size = header->aduSize();
        if (rest.size() < size)
            break;
        frames.emplace_back(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(size));
        at += size;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(at));
    return frames;
}

void TcpDeframer::reset()
{
    m_buffer.clear();
    m_error.reset();
}

} // namespace vt::dev::modbus
