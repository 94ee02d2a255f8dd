#include "node_image_adapter.h"

#include "access/hcs_rows.h"
#include "access/wire_value.h"
#include "hcs/exceptions.h"
#include "hcs/node_rules.h"
#include "hcs/telegram.h"

#include <algorithm>
#include <type_traits>
#include <variant>

namespace vt::dev::access {

namespace {

constexpr std::uint16_t kVersId = 0;  // OPAT manual §4 / DMA manuals: "Vers", raw = version × 100
constexpr std::uint16_t kModeId = 95; // E00, the mode of the module
// The shortest input image that still carries an error frame (OPAT manual §2.3: 4 bytes).
constexpr std::size_t kMinImage = hcs::kExceptionSize;

Reply mismatch()
{
    Reply reply;
    reply.status = ReplyStatus::Mismatch;
    return reply;
}

bool validModule(const Transaction &t)
{
    return t.module >= 0 && t.module <= 0xFF;
}

std::uint8_t sadrOf(const Transaction &t)
{
    return static_cast<std::uint8_t>(t.module & 0xFF);
}

std::uint8_t commandOf(const Transaction &t)
{
    return t.kind == TransactionKind::Write ? hcs::kCmdWrite : hcs::kCmdRead;
}

// First ID and count of a read (identify steps included); nullopt when the rows are not a run of
// consecutive IDs.
std::optional<hcs::ReadBlock> readBlockOf(const Transaction &t)
{
    if (t.kind == TransactionKind::Identify)
        return hcs::ReadBlock{t.step == 0 ? kVersId : kModeId, 1};
    if (t.rows.empty() || t.rows.size() > hcs::kMaxReadCount)
        return std::nullopt;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const ParamMeta *row = t.rows[i];
        if (!row || !row->id || *row->id < 0 || *row->id > 0xFFFF ||
            static_cast<std::size_t>(*row->id) != static_cast<std::size_t>(*t.rows.front()->id) + i)
            return std::nullopt;
    }
    return hcs::ReadBlock{static_cast<std::uint16_t>(*t.rows.front()->id),
                          static_cast<std::uint16_t>(t.rows.size())};
}

std::optional<hcs::WriteRequest> writeRequestOf(const Transaction &t, std::uint8_t tadr)
{
    if (t.rows.size() != 1 || t.values.size() != 1 || !t.rows.front() || !t.rows.front()->id ||
        *t.rows.front()->id < 0 || *t.rows.front()->id > 0xFFFF)
        return std::nullopt;
    const auto word = hcsWordOf(*t.rows.front(), t.values.front());
    if (!word)
        return std::nullopt;
    return hcs::WriteRequest{tadr, sadrOf(t), static_cast<std::uint16_t>(*t.rows.front()->id),
                             *word};
}

bool allZero(std::span<const std::uint8_t> bytes)
{
    return std::all_of(bytes.begin(), bytes.end(), [](std::uint8_t b) { return b == 0; });
}

} // namespace

NodeImageLayout defaultNodeImageLayout(hcs::Family family)
{
    if (family == hcs::Family::Opat)
        return {43, 43};
    return {};
}

NodeImageAdapter::NodeImageAdapter(hcs::Family family)
    : NodeImageAdapter(family, defaultNodeImageLayout(family))
{
}

NodeImageAdapter::NodeImageAdapter(hcs::Family family, NodeImageLayout layout)
    : m_family(family), m_layout(layout)
{
    m_layout.outputBytes = std::max(m_layout.outputBytes, kMinImage);
    m_layout.inputBytes = std::max(m_layout.inputBytes, kMinImage);
}

std::vector<Transaction> NodeImageAdapter::planRead(int module,
                                                    std::span<const ParamMeta *const> rows) const
{
    // OPAT manual §2.2: the answer is 4 + 2 × N bytes; it must fit the input image.
    const std::size_t fit = (m_layout.inputBytes - 4) / 2;
    const auto perBlock =
        static_cast<std::uint16_t>(std::min<std::size_t>(hcs::kMaxReadCount, fit));
    if (perBlock == 0)
        return {};
    return planHcsReads(module, rows, perBlock);
}

std::vector<Transaction> NodeImageAdapter::planIdentify(int module) const
{
    return planHcsIdentify(module);
}

Bytes NodeImageAdapter::encode(const Transaction &t)
{
    if (t.kind == TransactionKind::Raw)
        return t.raw;
    if (!validModule(t))
        return {};
    Bytes telegram;
    const auto tadr = static_cast<std::uint8_t>(m_tadr + 1);
    if (t.kind == TransactionKind::Write) {
        const auto request = writeRequestOf(t, tadr);
        if (!request)
            return {};
        telegram = hcs::encode(*request);
    } else {
        const auto block = readBlockOf(t);
        if (!block)
            return {};
        telegram = hcs::encode(hcs::ReadRequest{tadr, sadrOf(t), block->firstId, block->count});
    }
    if (telegram.size() > m_layout.outputBytes)
        return {};
    m_tadr = tadr;
    telegram.resize(m_layout.outputBytes, 0); // the rest of the output image
    return telegram;
}

std::size_t NodeImageAdapter::expectedReplyBytes(const Transaction &) const
{
    return m_layout.inputBytes;
}

// nullopt: `image` is no node answer at all (alignment lost). Otherwise the reply to `t`, or
// Mismatch for a well-formed answer to something else.
std::optional<Reply> NodeImageAdapter::imageReply(std::span<const std::uint8_t> image,
                                                  const Transaction &t) const
{
    const auto decoded = hcs::decodeResponse(image, hcs::DecodeOptions{m_family, true});
    if (!decoded)
        return std::nullopt;
    if (t.kind == TransactionKind::Raw)
        return Reply{};
    const std::uint8_t command = commandOf(t);
    return std::visit(
        [&](const auto &r) -> Reply {
            using T = std::decay_t<decltype(r)>;
            if constexpr (std::is_same_v<T, hcs::CyclicResponse>) {
                return mismatch();
            } else {
                if (r.tadr != m_tadr || r.sadr != sadrOf(t))
                    return mismatch(); // a late answer to an earlier attempt, or another module
                Reply reply;
                if constexpr (std::is_same_v<T, hcs::ExceptionResponse>) {
                    if (r.command != command)
                        return mismatch();
                    // OPAT manual §2.3 / §2.6, DMA Profinet manual §3.3 / §3.6.
                    reply.status = ReplyStatus::DeviceException;
                    reply.exceptionCode = r.code;
                    reply.exceptionText = hcs::exceptionTextOrUnknown(m_family, r.command, r.code);
                } else if constexpr (std::is_same_v<T, hcs::ReadResponse>) {
                    const auto block = command == hcs::kCmdRead ? readBlockOf(t) : std::nullopt;
                    if (!block || r.values.size() != block->count)
                        return mismatch();
                    for (std::size_t i = 0; i < r.values.size(); ++i)
                        reply.values.emplace_back(t.kind == TransactionKind::Read
                                                      ? registerToRaw(*t.rows[i], r.values[i])
                                                      : static_cast<double>(r.values[i]));
                    if (t.kind == TransactionKind::Identify) {
                        (t.step == 0 ? reply.identity.versRaw : reply.identity.mode) =
                            r.values.front();
                    }
                } else {
                    // OPAT manual §2.5: the write answer echoes ID and value.
                    const auto asked =
                        command == hcs::kCmdWrite ? writeRequestOf(t, m_tadr) : std::nullopt;
                    if (!asked || r.id != asked->id || r.value != asked->value)
                        return mismatch();
                    reply.values.emplace_back(registerToRaw(*t.rows.front(), r.value));
                }
                return reply;
            }
        },
        *decoded);
}

std::optional<Reply> NodeImageAdapter::feed(std::span<const std::uint8_t> bytes,
                                            const Transaction &t)
{
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::optional<Reply> result;
    std::size_t used = 0;
    while (m_buffer.size() - used >= m_layout.inputBytes) {
        const auto image =
            std::span<const std::uint8_t>(m_buffer).subspan(used, m_layout.inputBytes);
        std::optional<Reply> reply =
            allZero(image) && !m_resync ? mismatch() : imageReply(image, t);
        // While out of step, only the answer to `t` (TADR, SADR, CMD) re-establishes alignment:
        // a window that merely decodes may start inside another image.
        if (!reply || (m_resync && reply->status == ReplyStatus::Mismatch)) {
            m_resync = true;
            ++used;
            continue;
        }
        m_resync = false;
        used += m_layout.inputBytes;
        reply->frame.assign(image.begin(), image.end());
        if (offerReply(result, std::move(*reply)))
            break;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(used));
    return result;
}

void NodeImageAdapter::resetFraming()
{
    // Dropping part of an image leaves the rest of it to arrive later: out of step until the
    // next answer is found.
    if (!m_buffer.empty())
        m_resync = true;
    m_buffer.clear();
}

} // namespace vt::dev::access
