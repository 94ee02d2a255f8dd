#include "arg_parse.h"

namespace vt::cmdline {

std::optional<QString> takeOption(QStringList &args, const QString &name, bool *missing)
{
    const qsizetype i = args.indexOf(name);
    if (i < 0)
        return std::nullopt;
    if (i + 1 >= args.size()) {
        if (missing)
            *missing = true;
        args.removeAt(i);
        return std::nullopt;
    }
    const QString value = args.at(i + 1);
    args.remove(i, 2);
    return value;
}

bool takeFlag(QStringList &args, const QString &name)
{
    return args.removeAll(name) > 0;
}

std::optional<long long> parseInteger(const QString &text, long long min, long long max)
{
    bool ok = false;
    QString t = text.trimmed();
    long long v = 0;
    const bool negative = t.startsWith('-');
    if (negative)
        t.remove(0, 1);
    if (t.startsWith("0x", Qt::CaseInsensitive))
        v = t.mid(2).toLongLong(&ok, 16);
    else
        v = t.toLongLong(&ok, 10);
    if (!ok || t.isEmpty())
        return std::nullopt;
    if (negative)
        v = -v;
    if (v < min || v > max)
        return std::nullopt;
    return v;
}

} // namespace vt::cmdline
