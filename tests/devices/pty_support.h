// Test support: a pseudo-terminal pair for tests that put a real Modbus master (libmodbus) on
// one side of a serial line and ValveTune's code on the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fcntl.h>
#include <stdlib.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace vt::test {

// The master side stays with the test; the slave path is what the peer opens.
class Pty
{
public:
    Pty()
    {
        m_master = posix_openpt(O_RDWR | O_NOCTTY);
        if (m_master >= 0 && grantpt(m_master) == 0 && unlockpt(m_master) == 0)
            if (const char *name = ptsname(m_master))
                m_slaveName = name;
    }
    ~Pty()
    {
        if (m_master >= 0)
            close(m_master);
    }
    Pty(const Pty &) = delete;
    Pty &operator=(const Pty &) = delete;

    bool ok() const { return m_master >= 0 && !m_slaveName.empty(); }
    int fd() const { return m_master; }
    const std::string &slaveName() const { return m_slaveName; }

private:
    int m_master = -1;
    std::string m_slaveName;
};

inline bool writeAll(int fd, const std::vector<std::uint8_t> &bytes)
{
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

} // namespace vt::test
