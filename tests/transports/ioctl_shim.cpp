// TEST-ONLY tty shim, linked into vt_transports_tests and nothing else; production code is
// unchanged. Two things make libserialport unusable on a pseudo-terminal, and this file
// interposes the libc calls behind them for the whole test process:
//  - ioctl(): sp_open() reads the modem control lines (TIOCMGET), which a pty lacks (ENOTTY).
//    Every call goes to the real ioctl() first; only when that fails with ENOTTY are TIOCMGET,
//    TIOCMSET, TIOCMBIS and TIOCMBIC answered from a process-wide fake register.
//  - tcsetattr(): the pty driver forces CS8 and clears PARENB, and the kernel answers EINVAL
//    when a request's only changes are bits it dropped (e.g. re-applying 8E1 to a pty that
//    already has everything else). A UART accepts that request, so on a pty slave exactly that
//    EINVAL becomes success. Every request is recorded for lastTermiosRequest().
#include "ioctl_shim.h"

#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstring>
#include <dlfcn.h>
#include <map>
#include <mutex>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

namespace {

template<typename Fn> Fn nextSymbol(const char *name)
{
    void *symbol = dlsym(RTLD_NEXT, name);
    Fn f = nullptr;
    static_assert(sizeof f == sizeof symbol);
    std::memcpy(&f, &symbol, sizeof f); // object → function pointer without a cast warning
    return f;
}

using IoctlFn = int (*)(int, unsigned long, ...);
using TcsetattrFn = int (*)(int, int, const termios *);

std::atomic<int> g_modemLines{TIOCM_DTR | TIOCM_RTS | TIOCM_CTS | TIOCM_DSR | TIOCM_CAR};

std::mutex g_mutex;
std::map<dev_t, termios> &requests()
{
    static std::map<dev_t, termios> map;
    return map;
}

bool ptySlave(int fd, dev_t *device)
{
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode))
        return false;
    *device = st.st_rdev;
    const unsigned majorNumber = major(st.st_rdev);
    return majorNumber >= 136 && majorNumber <= 143; // UNIX98 pty slaves
}

// True when `wanted` differs from `current` only in the bits a pty cannot store.
bool onlyUnstorableBitsDiffer(const termios &current, const termios &wanted)
{
    const tcflag_t unstorable = PARENB | CSIZE;
    return current.c_iflag == wanted.c_iflag && current.c_oflag == wanted.c_oflag &&
           current.c_lflag == wanted.c_lflag &&
           (current.c_cflag & ~unstorable) == (wanted.c_cflag & ~unstorable) &&
           std::memcmp(current.c_cc, wanted.c_cc, sizeof current.c_cc) == 0 &&
           cfgetispeed(&current) == cfgetispeed(&wanted) &&
           cfgetospeed(&current) == cfgetospeed(&wanted);
}

} // namespace

namespace vt::test {

bool lastTermiosRequest(dev_t device, termios *out)
{
    std::lock_guard lock(g_mutex);
    const auto it = requests().find(device);
    if (it == requests().end())
        return false;
    *out = it->second;
    return true;
}

} // namespace vt::test

extern "C" int ioctl(int fd, unsigned long request, ...) noexcept
{
    va_list args;
    va_start(args, request);
    void *argument = va_arg(args, void *);
    va_end(args);

    static const IoctlFn real = nextSymbol<IoctlFn>("ioctl");
    const int result = real ? real(fd, request, argument) : (errno = ENOSYS, -1);
    if (result >= 0 || errno != ENOTTY || !argument)
        return result;

    int *bits = static_cast<int *>(argument);
    switch (request) {
    case TIOCMGET: *bits = g_modemLines.load(); break;
    case TIOCMSET: g_modemLines.store(*bits); break;
    case TIOCMBIS: g_modemLines.fetch_or(*bits); break;
    case TIOCMBIC: g_modemLines.fetch_and(~*bits); break;
    default: return result; // errno is still ENOTTY
    }
    return 0;
}

extern "C" int tcsetattr(int fd, int actions, const termios *wanted) noexcept
{
    static const TcsetattrFn real = nextSymbol<TcsetattrFn>("tcsetattr");
    if (!real) {
        errno = ENOSYS;
        return -1;
    }
    dev_t device = 0;
    const bool pty = wanted && ptySlave(fd, &device);
    if (pty) {
        std::lock_guard lock(g_mutex);
        requests()[device] = *wanted;
    }
    const int result = real(fd, actions, wanted);
    if (result < 0 && errno == EINVAL && pty) {
        termios current;
        if (::tcgetattr(fd, &current) == 0 && onlyUnstorableBitsDiffer(current, *wanted))
            return 0;
        errno = EINVAL;
    }
    return result;
}
