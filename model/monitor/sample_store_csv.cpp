// SampleStore's CSV export and its bounded reader (round trips, loading a saved recording).
#include "model/text_language.h"
#include "sample_store.h"

#include <QIODevice>
#include <QLocale>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace vt::model {

namespace {

// The file's separator and decimal sign follow the language (the default QLocale, which the
// app's language switch sets): English ',' and '.', German ';' and ',' — what spreadsheets expect
// in each (German and English issue: "CSV export states its separator and decimal sign"). The
// first line carries the separator ("# ValveTune samples,1" / "# ValveTune samples;1"), the
// decimal sign follows from it, and the second line states both in words for people. Files of
// the first version (always ',' and '.') read unchanged.
struct CsvFormat
{
    char separator = ',';
    char decimal = '.';
};

constexpr CsvFormat kEnglishCsv{',', '.'};
constexpr CsvFormat kGermanCsv{';', ','};
constexpr char kMagicPrefix[] = "# ValveTune samples";
constexpr char kMagicVersion[] = "1";
constexpr char kChannelPrefix[] = "# channel";
constexpr qsizetype kWriteChunk = 64 * 1024;

CsvFormat writeFormat()
{
    return textLanguage() == dev::Language::German ? kGermanCsv : kEnglishCsv;
}

QByteArray formatStatement(const CsvFormat &format)
{
    return format.separator == ';'
               ? QByteArray(
                     "# Trennzeichen: Semikolon (;). Dezimalzeichen: Komma (,). Kodierung: UTF-8.")
               : QByteArray("# Separator: comma (,). Decimal sign: point (.). Encoding: UTF-8.");
}

// Shortest text that reads back to the same number, independent of the locale, with the
// file's decimal sign.
template<typename T> void appendNumber(QByteArray &line, T value, const CsvFormat &format)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    if (format.decimal != '.')
        std::replace(buf, r.ptr, '.', format.decimal);
    line.append(buf, static_cast<qsizetype>(r.ptr - buf));
}

// Times in seconds to the microsecond: finer digits of a steady clock are noise, and a reader
// should not see 196.63327260100002.
void appendTime(QByteArray &line, double seconds, const CsvFormat &format)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, seconds, std::chars_format::fixed, 6);
    if (format.decimal != '.')
        std::replace(buf, r.ptr, '.', format.decimal);
    line.append(buf, static_cast<qsizetype>(r.ptr - buf));
}

// Marker texts and channel names are one line each: a line break would end the CSV row.
QByteArray csvField(QString text, const CsvFormat &format)
{
    text.replace(QLatin1Char('\r'), QLatin1Char(' ')).replace(QLatin1Char('\n'), QLatin1Char(' '));
    if (text.contains(QLatin1Char(format.separator)) || text.contains(QLatin1Char('"'))) {
        text.replace(QLatin1String("\""), QLatin1String("\"\""));
        text = QLatin1Char('"') + text + QLatin1Char('"');
    }
    return text.toUtf8();
}

// RFC 4180 fields of one line; false for an unterminated quote.
bool splitCsv(const QString &line, QStringList &fields, const CsvFormat &format)
{
    fields.clear();
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c != QLatin1Char('"'))
                field += c;
            else if (i + 1 < line.size() && line[i + 1] == QLatin1Char('"'))
                field += line[++i];
            else
                quoted = false;
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(format.separator)) {
            fields.append(field);
            field.clear();
        } else {
            field += c;
        }
    }
    fields.append(field);
    return !quoted;
}

template<typename T> bool parseNumber(const QString &text, T &value, const CsvFormat &format)
{
    QByteArray latin = text.trimmed().toLatin1();
    if (format.decimal != '.') {
        if (latin.contains('.'))
            return false; // a point is no decimal sign here; reading it as one would shift values
        latin.replace(format.decimal, '.');
    }
    const char *end = latin.constData() + latin.size();
    const auto r = std::from_chars(latin.constData(), end, value);
    return !latin.isEmpty() && r.ec == std::errc() && r.ptr == end;
}

// The format a first line announces; nullopt when it is no sample file's first line.
std::optional<CsvFormat> formatOfMagic(const QString &line)
{
    for (const CsvFormat &f : {kEnglishCsv, kGermanCsv})
        if (line ==
            QLatin1String(kMagicPrefix) + QLatin1Char(f.separator) + QLatin1String(kMagicVersion))
            return f;
    return std::nullopt;
}

} // namespace

bool SampleStore::writeCsv(QIODevice &out, QString *error) const
{
    return writeCsv(out, -std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(), error);
}

bool SampleStore::writeCsv(QIODevice &out, double t0, double t1, QString *error) const
{
    QByteArray buf;
    const auto put = [&](bool force) {
        if (buf.size() < kWriteChunk && !force)
            return true;
        const bool ok = out.write(buf) == buf.size();
        buf.clear();
        if (!ok && error)
            *error = out.errorString();
        return ok;
    };
    const CsvFormat format = writeFormat();
    const char sep = format.separator;
    buf += kMagicPrefix;
    buf += sep;
    buf += kMagicVersion;
    buf += '\n' + formatStatement(format) + '\n';
    for (const SampleChannel &c : m_channels)
        buf += kChannelPrefix + QByteArray(1, sep) + csvField(c.id, format) + sep +
               csvField(c.name, format) + sep + csvField(c.unit, format) + '\n';
    buf += "time_s";
    for (const SampleChannel &c : m_channels)
        buf += sep + csvField(c.id, format);
    buf += sep + QByteArray("marker\n");

    auto marker = std::lower_bound(m_markers.begin(), m_markers.end(), t0,
                                   [](const SampleMarker &m, double t) { return m.t < t; });
    const auto markerEnd =
        std::upper_bound(m_markers.begin(), m_markers.end(), t1,
                         [](double t, const SampleMarker &m) { return t < m.t; });
    const auto putMarkersBefore = [&](double limit, bool inclusive) {
        for (; marker != markerEnd && (marker->t < limit || (inclusive && marker->t == limit));
             ++marker) {
            appendTime(buf, marker->t, format);
            buf += QByteArray(channelCount() + 1, sep) + csvField(marker->text, format) + '\n';
        }
    };
    const qsizetype end = !(t0 <= t1) ? 0 : upperBound(t1);
    for (qsizetype i = !(t0 <= t1) ? 0 : lowerBound(t0); i < end; ++i) {
        const double t = timeAt(i);
        putMarkersBefore(t, false); // a marker at a sample's time follows that sample
        appendTime(buf, t, format);
        for (int c = 0; c < channelCount(); ++c) {
            buf += sep;
            const float v = column(c)[physical(i)];
            if (!std::isnan(v))
                appendNumber(buf, v, format);
        }
        buf += sep;
        buf += '\n';
        if (!put(false))
            return false;
    }
    putMarkersBefore(t1, true);
    return put(true);
}

std::optional<SampleStore> SampleStore::readCsv(QIODevice &in, QString *error,
                                                const SampleCsvLimits &limits)
{
    qsizetype lineNo = 0;
    const auto fail = [&](const QString &why) -> std::optional<SampleStore> {
        if (error)
            *error = lineNo > 0 ? tr("line %1: %2").arg(lineNo).arg(why) : why;
        return std::nullopt;
    };
    QString line;
    bool tooLong = false;
    const auto nextLine = [&]() {
        if (in.atEnd())
            return false;
        ++lineNo;
        QByteArray bytes = in.readLine(limits.maxLineLength + 3); // + CR LF and the terminating NUL
        tooLong = !bytes.endsWith('\n') && !in.atEnd();
        while (bytes.endsWith('\n') || bytes.endsWith('\r'))
            bytes.chop(1);
        tooLong = tooLong || bytes.size() > limits.maxLineLength;
        line = QString::fromUtf8(bytes);
        return true;
    };

    const std::optional<CsvFormat> found = nextLine() ? formatOfMagic(line) : std::nullopt;
    if (!found)
        return fail(tr("not a ValveTune sample file"));
    const CsvFormat format = *found;
    const QString channelPrefix = QLatin1String(kChannelPrefix) + QLatin1Char(format.separator);
    QList<SampleChannel> channels;
    QStringList fields;
    bool haveHeader = false;
    while (!haveHeader && nextLine()) {
        if (tooLong)
            return fail(tr("longer than %1 bytes").arg(limits.maxLineLength));
        if (line.startsWith(channelPrefix)) {
            if (!splitCsv(line.mid(channelPrefix.size()), fields, format) || fields.size() != 3)
                return fail(tr("a channel needs an id, a name and a unit"));
            if (channels.size() >= limits.maxChannels)
                return fail(tr("more than %1 channels").arg(limits.maxChannels));
            channels.append({fields[0], fields[1], fields[2]});
        } else if (!line.startsWith(QLatin1Char('#')) && !line.isEmpty()) {
            if (!splitCsv(line, fields, format) || fields.size() != channels.size() + 2 ||
                fields.front() != QLatin1String("time_s") ||
                fields.back() != QLatin1String("marker"))
                return fail(tr("the column header does not match the channels"));
            for (qsizetype c = 0; c < channels.size(); ++c)
                if (fields[c + 1] != channels[c].id)
                    return fail(tr("the column header does not match the channels"));
            haveHeader = true;
        }
    }
    if (!haveHeader)
        return fail(tr("the column header is missing"));

    std::vector<double> times;
    std::vector<float> values; // row-major, channels.size() per row
    std::deque<SampleMarker> markers;
    const auto width = static_cast<std::size_t>(channels.size());
    while (nextLine()) {
        if (tooLong)
            return fail(tr("longer than %1 bytes").arg(limits.maxLineLength));
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        if (!splitCsv(line, fields, format) || fields.size() != channels.size() + 2)
            return fail(tr("expected %1 columns").arg(channels.size() + 2));
        double t = 0;
        if (!parseNumber(fields[0], t, format) || !std::isfinite(t))
            return fail(tr("'%1' is not a time").arg(fields[0]));
        bool anyValue = false;
        for (qsizetype c = 1; c <= channels.size(); ++c)
            anyValue = anyValue || !fields[c].trimmed().isEmpty();
        if (!fields.back().isEmpty()) {
            markers.push_back({t, fields.back().left(kMaxMarkerText)});
            if (static_cast<qsizetype>(markers.size()) > limits.maxMarkers)
                markers.pop_front();
            if (!anyValue)
                continue;
        }
        if (static_cast<qsizetype>(times.size()) >= limits.maxRows)
            return fail(tr("more than %1 samples").arg(limits.maxRows));
        if (!times.empty() && t < times.back())
            return fail(tr("time goes backwards"));
        times.push_back(t);
        for (qsizetype c = 1; c <= channels.size(); ++c) {
            float v = std::numeric_limits<float>::quiet_NaN();
            if (!fields[c].trimmed().isEmpty() && !parseNumber(fields[c], v, format))
                return fail(tr("'%1' is not a number").arg(fields[c]));
            values.push_back(v);
        }
    }

    SampleStore store(std::move(channels), qMax<qsizetype>(1, static_cast<qsizetype>(times.size())),
                      limits.maxMarkers);
    std::vector<double> row(width);
    for (std::size_t r = 0; r < times.size(); ++r) {
        for (std::size_t c = 0; c < width; ++c)
            row[c] = static_cast<double>(values[r * width + c]);
        store.append(times[r], row);
    }
    for (const SampleMarker &m : markers)
        store.addMarker(m.t, m.text);
    return store;
}

} // namespace vt::model
