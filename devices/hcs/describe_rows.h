// Internal to hcs/describe*.cpp: the row helpers shared by the CMD 3/6 and CMD 15 describers.
#pragma once

#include "core/byte_reader.h"
#include "core/field_span.h"
#include "describe.h"

#include <string>
#include <vector>

namespace vt::dev::hcs::detail {

struct Rows
{
    std::vector<FieldSpan> &out;

    void add(std::string key, std::size_t offset, std::size_t length, int depth, std::string value,
             LocalText text)
    {
        out.push_back(
            FieldSpan{std::move(key), offset, length, depth, std::move(value), std::move(text)});
    }
};

// "slave address: OPAT master" / "module with E22 = 3".
LocalText sadrText(Family family, std::uint8_t sadr, Direction direction);
LocalText join(const LocalText &a, const LocalText &b, const char *sep = ": ");

// CMD 15 rows after the 3-byte header (describe_cmd15.cpp). They return false when the frame
// ends inside the telegram.
bool describeCyclicRequest(Rows &rows, ByteReader &r, std::uint8_t snum,
                           const DescribeOptions &options);
bool describeCyclicResponse(Rows &rows, ByteReader &r, std::uint8_t sadr,
                            const DescribeOptions &options);

} // namespace vt::dev::hcs::detail
