// Test support for cross-checks against Wireshark's dissectors: writes a classic pcap file and
// runs tshark on it (bounded by `timeout`, no sleeps). Header-only; shared by the HART and the
// CANopen tshark tests. Tests call GTEST_SKIP when tshark or a dissector is missing.
#pragma once

#include "core/byte_writer.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace vt::test {

inline constexpr std::uint32_t kLinktypeRawIp = 101;     // LINKTYPE_RAW: IPv4/IPv6 packets
inline constexpr std::uint32_t kLinktypeSocketCan = 227; // LINKTYPE_CAN_SOCKETCAN

struct CommandResult
{
    int status = -1;
    std::string output;
};

// Runs `command` through the shell and returns its stdout (stderr goes to /dev/null).
inline CommandResult runCommand(const std::string &command)
{
    CommandResult result;
    FILE *pipe = ::popen((command + " 2>/dev/null").c_str(), "r");
    if (!pipe)
        return result;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
        result.output.append(buffer, n);
    result.status = ::pclose(pipe);
    return result;
}

inline bool haveProgram(const std::string &name)
{
    return !runCommand("command -v " + name).output.empty();
}

inline std::string tsharkCommand()
{
    // `timeout` bounds a hung tshark; without coreutils the test still runs, unbounded.
    return haveProgram("timeout") ? "timeout 120 tshark" : "tshark";
}

// True when this tshark knows `field` (a dissector may be missing in a stripped build).
inline bool tsharkHasField(const std::string &field)
{
    const CommandResult r = runCommand("tshark -G fields");
    return r.output.find("\t" + field + "\t") != std::string::npos;
}

class PcapWriter
{
public:
    explicit PcapWriter(std::uint32_t linktype) : m_linktype(linktype) {}

    void add(const dev::Bytes &packet) { m_packets.push_back(packet); }

    bool write(const std::filesystem::path &path) const
    {
        dev::ByteWriter w;
        u32le(w, 0xA1B2C3D4u); // microsecond pcap, written little-endian
        w.u16le(2).u16le(4);
        u32le(w, 0); // thiszone
        u32le(w, 0); // sigfigs
        u32le(w, 65535);
        u32le(w, m_linktype);
        std::uint32_t second = 0;
        for (const dev::Bytes &p : m_packets) {
            u32le(w, second++);
            u32le(w, 0);
            u32le(w, static_cast<std::uint32_t>(p.size()));
            u32le(w, static_cast<std::uint32_t>(p.size()));
            w.bytes(p);
        }
        std::ofstream out(path, std::ios::binary);
        const dev::Bytes &bytes = w.data();
        out.write(reinterpret_cast<const char *>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        return static_cast<bool>(out);
    }

private:
    static void u32le(dev::ByteWriter &w, std::uint32_t v)
    {
        w.u16le(static_cast<std::uint16_t>(v)).u16le(static_cast<std::uint16_t>(v >> 16));
    }

    std::uint32_t m_linktype;
    std::vector<dev::Bytes> m_packets;
};

// IPv4 + UDP around `payload` (checksums 0 = not computed, which tshark accepts).
inline dev::Bytes ipv4Udp(const dev::Bytes &payload, std::uint16_t sourcePort,
                          std::uint16_t destinationPort)
{
    dev::ByteWriter w;
    const auto udpLength = static_cast<std::uint16_t>(8 + payload.size());
    w.u8(0x45).u8(0).u16be(static_cast<std::uint16_t>(20 + udpLength)).u16be(0).u16be(0);
    w.u8(64).u8(17).u16be(0).u32be(0x7F000001).u32be(0x7F000001);
    w.u16be(sourcePort).u16be(destinationPort).u16be(udpLength).u16be(0);
    w.bytes(payload);
    return w.take();
}

// A temporary file removed when the object goes out of scope.
class TempFile
{
public:
    explicit TempFile(const std::string &stem)
        : m_path(std::filesystem::temp_directory_path() /
                 (stem + "_" + std::to_string(::getpid()) + ".pcap"))
    {
    }
    ~TempFile()
    {
        std::error_code ec;
        std::filesystem::remove(m_path, ec);
    }
    const std::filesystem::path &path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

// tshark -T fields: one row per packet, one column per field (several occurrences joined by ',').
inline std::vector<std::vector<std::string>> tsharkFields(const std::filesystem::path &file,
                                                          const std::vector<std::string> &fields,
                                                          const std::string &extraArgs, int *status)
{
    std::string cmd =
        tsharkCommand() + " -n -r '" + file.string() + "' " + extraArgs + " -T fields -E header=n";
    for (const std::string &f : fields)
        cmd += " -e " + f;
    const CommandResult r = runCommand(cmd);
    if (status)
        *status = r.status;
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(r.output);
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> row;
        std::size_t start = 0;
        for (;;) {
            const std::size_t tab = line.find('\t', start);
            row.push_back(
                line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
            if (tab == std::string::npos)
                break;
            start = tab + 1;
        }
        row.resize(fields.size());
        rows.push_back(std::move(row));
    }
    return rows;
}

inline std::string lower(std::string s)
{
    for (char &c : s)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return s;
}

// "0x1e", "30" → 30; empty or garbage → -1.
inline long number(const std::string &s)
{
    if (s.empty())
        return -1;
    try {
        std::size_t used = 0;
        const long v = std::stol(s, &used, 0);
        return used == s.size() ? v : -1;
    } catch (...) {
        return -1;
    }
}

} // namespace vt::test
