#include "frame_links.h"

#include "dict/dictionary.h"
#include "inspect/frame_parameters.h"
#include "transports/byte_span.h"

#include <span>

namespace vt::model {
namespace {

QStringList namesOf(const TelegramRecord &r, const vt::dev::Dictionary &dictionary,
                    vt::dev::hcs::Family family, const vt::dev::inspect::ImageLayout &layout)
{
    QStringList names;
    const auto link = r.linkProtocol();
    if (!link)
        return names;
    const auto carried = vt::dev::inspect::carriedBy(*link, vt::link::byteSpan(r.bytes),
                                                     r.direction, family, layout);
    for (const vt::dev::ParamMeta *p : vt::dev::inspect::rowsOf(carried, dictionary))
        names << QString::fromStdString(p->name);
    return names;
}

} // namespace

std::optional<quint64> requestSeqOf(const TelegramLog &log, quint64 seq)
{
    const TelegramRecord *r = log.find(seq);
    if (!r)
        return std::nullopt;
    if (r->direction == vt::dev::Direction::Request)
        return seq;
    for (quint64 s = seq; s > log.firstSeq();) {
        --s;
        const TelegramRecord *q = log.find(s);
        if (q && q->direction == vt::dev::Direction::Request && q->module == r->module)
            return s;
    }
    return std::nullopt;
}

QStringList parametersOfRecord(const TelegramLog &log, quint64 seq,
                               const vt::dev::Dictionary &dictionary, vt::dev::hcs::Family family,
                               const vt::dev::inspect::ImageLayout &layout)
{
    const auto request = requestSeqOf(log, seq);
    const TelegramRecord *r = request ? log.find(*request) : nullptr;
    return r ? namesOf(*r, dictionary, family, layout) : QStringList{};
}

QList<quint64> lastFramesFor(const TelegramLog &log, int module, const QString &parameterName,
                             const vt::dev::Dictionary &dictionary, vt::dev::hcs::Family family,
                             const vt::dev::inspect::ImageLayout &layout)
{
    QList<quint64> out;
    for (qsizetype i = log.size(); i-- > 0;) {
        const TelegramRecord &r = log.at(i);
        if (r.direction != vt::dev::Direction::Request || (module >= 0 && r.module != module))
            continue;
        if (!namesOf(r, dictionary, family, layout).contains(parameterName))
            continue;
        out << r.seq;
        // Everything of this module up to its next request answers this one.
        for (qsizetype k = i + 1; k < log.size(); ++k) {
            const TelegramRecord &a = log.at(k);
            if (a.module != r.module)
                continue;
            if (a.direction == vt::dev::Direction::Request)
                break;
            out << a.seq;
        }
        break;
    }
    return out;
}

} // namespace vt::model
