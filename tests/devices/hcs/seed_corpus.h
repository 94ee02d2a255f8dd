// Fuzz seed corpora = the manuals' worked examples, kept in step with the tests: with
// VT_WRITE_CORPUS=1 the corpus tests (re)write tests/fuzz/corpus/<fuzzer>/<name>.bin, otherwise
// they check that every seed is on disk with the right bytes.
#pragma once

#include "core/byte_writer.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>

namespace vt::test {

inline std::filesystem::path corpusDir(const std::string &fuzzer)
{
    const char *env = std::getenv("VT_SOURCE_DIR");
    const std::filesystem::path root = env != nullptr && *env != '\0' ? env : VT_SOURCE_DIR;
    return root / "tests" / "fuzz" / "corpus" / fuzzer;
}

inline void checkOrWriteSeed(const std::string &fuzzer, const std::string &name,
                             const vt::dev::Bytes &content)
{
    const std::filesystem::path file = corpusDir(fuzzer) / (name + ".bin");
    const char *write = std::getenv("VT_WRITE_CORPUS");
    if (write != nullptr && std::string(write) == "1") {
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char *>(content.data()),
                  static_cast<std::streamsize>(content.size()));
        ASSERT_TRUE(out.good()) << file;
        return;
    }
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(in.good()) << file << " is missing; run the tests once with VT_WRITE_CORPUS=1";
    const vt::dev::Bytes onDisk{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
    EXPECT_EQ(onDisk, content) << file << " is stale; run the tests once with VT_WRITE_CORPUS=1";
}

} // namespace vt::test
