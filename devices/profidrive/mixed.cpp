#include "mixed.h"

#include "core/decode_helpers.h"

namespace vt::dev::profidrive {
namespace {

DecodeError shifted(DecodeError e)
{
    e.offset += kTelegram1Size;
    return e;
}

} // namespace

Result<Bytes, DecodeError> encode(const MixedRequest &request, hcs::Family family)
{
    auto node = hcs::encode(request.node, family);
    if (!node.ok())
        return shifted(node.error());
    ByteWriter w;
    w.bytes(encode(request.drive)).bytes(*node);
    return w.take();
}

Bytes encode(const MixedResponse &response)
{
    ByteWriter w;
    w.bytes(encode(response.drive));
    std::visit([&w](const auto &node) { w.bytes(hcs::encode(node)); }, response.node);
    return w.take();
}

Result<MixedRequest, DecodeError> decodeMixedRequest(std::span<const std::uint8_t> image,
                                                     const hcs::DecodeOptions &options)
{
    auto drive = decodeSetpoint(image, true);
    if (!drive.ok())
        return drive.error();
    auto node = hcs::decodeCyclicRequest(image.subspan(kTelegram1Size), options);
    if (!node.ok())
        return shifted(node.error());
    return MixedRequest{*drive, std::move(node).value()};
}

Result<MixedResponse, DecodeError> decodeMixedResponse(std::span<const std::uint8_t> image,
                                                       const hcs::DecodeOptions &options)
{
    auto drive = decodeActual(image, true);
    if (!drive.ok())
        return drive.error();
    auto node = hcs::decodeResponse(image.subspan(kTelegram1Size), options);
    if (!node.ok())
        return shifted(node.error());
    if (auto *c = std::get_if<hcs::CyclicResponse>(&*node))
        return MixedResponse{*drive, *c};
    if (auto *e = std::get_if<hcs::ExceptionResponse>(&*node);
        e != nullptr && e->command == hcs::kCmdCyclic)
        return MixedResponse{*drive, *e};
    return decodeError(DecodeErrc::UnexpectedCommand, kTelegram1Size + 2,
                       "the node part of a mixed image is a CMD 15 response");
}

} // namespace vt::dev::profidrive
