// fuzz_inspect_paste: the inspector's decode box end to end on untrusted text — parseHexInput
// (tolerant hex, candump), detectProtocol, describeAny / describeLogged for every protocol and
// log key, carriedBy. Properties: no crash; input beyond the bounds is refused; every field lies
// inside its frame; an auto-detected protocol decodes in the directions it claims.
#include "fuzz_require.h"
#include "inspect/auto_detect.h"
#include "inspect/frame_parameters.h"
#include "inspect/hex_input.h"
#include "inspect/logged_frame.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

using namespace vt::dev;
using namespace vt::dev::inspect;

namespace {

using vt::fuzz::require;

void checkFields(const Description &d, std::size_t size)
{
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= size);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    const auto input = parseHexInput(text);
    if (!input.ok())
        return 0;
    require(text.size() <= kMaxInputChars && input->bytes.size() <= kMaxFrameBytes);
    const auto &bytes = input->bytes;

    const Detection detection = detectProtocol(bytes, input->cobId);
    if (const Candidate *c = detection.choice()) {
        for (Direction dir : c->directions) {
            AnyOptions o;
            o.protocol = c->protocol;
            o.direction = dir;
            o.cobId = input->cobId;
            if (!c->families.empty())
                o.family = c->families.front();
            const auto d = c->protocol == FrameFormat::Gateway
                               ? describeLogged(LinkProtocol::NodeImage, bytes, o)
                               : describeAny(bytes, o);
            require(d.ok());
            checkFields(*d, bytes.size());
        }
    }
    for (Direction dir : {Direction::Request, Direction::Response}) {
        AnyOptions o;
        o.direction = dir;
        o.cobId = input->cobId;
        for (FrameFormat format : kFrameFormats) {
            o.protocol = format;
            const auto d = describeAny(bytes, o);
            if (d.ok())
                checkFields(*d, bytes.size());
        }
        for (LinkProtocol link : kLinkProtocols) {
            const auto d = describeLogged(link, bytes, o);
            if (d.ok())
                checkFields(*d, bytes.size());
            (void)carriedBy(link, bytes, dir);
        }
    }
    return 0;
}
