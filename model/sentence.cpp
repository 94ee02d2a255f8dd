#include "model/sentence.h"

#include "model/text_language.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>

namespace vt::model {

Sentence::Sentence(const char *context, const char *source) : m_context(context), m_source(source)
{
}

Sentence Sentence::verbatim(QString text)
{
    Sentence s;
    s.m_whole = std::move(text);
    return s;
}

Sentence Sentence::bilingual(dev::LocalText text)
{
    Sentence s;
    s.m_whole = std::move(text);
    return s;
}

bool Sentence::isEmpty() const
{
    if (m_source)
        return false;
    if (const auto *plain = std::get_if<QString>(&m_whole))
        return plain->isEmpty();
    if (const auto *local = std::get_if<dev::LocalText>(&m_whole))
        return local->en.empty() && local->de.empty();
    return false;
}

Sentence &Sentence::arg(const QString &value)
{
    m_args.emplace_back(value);
    return *this;
}

Sentence &Sentence::arg(long long value)
{
    m_args.emplace_back(QString::number(value));
    return *this;
}

Sentence &Sentence::arg(const dev::LocalText &value)
{
    m_args.emplace_back(value);
    return *this;
}

Sentence &Sentence::arg(const Sentence &value)
{
    m_args.emplace_back(std::make_shared<const Sentence>(value));
    return *this;
}

namespace {

// The place number of a "%n" (1..99) starting at `at`, and its length; 0 when there is none.
int placeAt(const QString &pattern, qsizetype at, qsizetype *length)
{
    if (pattern[at] != QLatin1Char('%') || at + 1 >= pattern.size() || !pattern[at + 1].isDigit())
        return 0;
    int number = pattern[at + 1].digitValue();
    *length = 2;
    if (at + 2 < pattern.size() && pattern[at + 2].isDigit()) {
        number = number * 10 + pattern[at + 2].digitValue();
        *length = 3;
    }
    return number;
}

// Fills every place in one pass, as QString::arg() numbers them (the lowest %n takes the first
// value), but a "%1" inside a value stays as it is instead of being filled by the next value.
QString fill(const QString &pattern, const QStringList &values)
{
    std::vector<int> places;
    for (qsizetype i = 0, length = 0; i < pattern.size(); ++i)
        if (const int n = placeAt(pattern, i, &length); n > 0)
            places.push_back(n);
    std::sort(places.begin(), places.end());
    places.erase(std::unique(places.begin(), places.end()), places.end());

    QString out;
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        qsizetype length = 0;
        const int n = placeAt(pattern, i, &length);
        const auto rank = std::lower_bound(places.begin(), places.end(), n) - places.begin();
        if (n > 0 && rank < values.size()) {
            out += values[rank];
            i += length - 1;
        } else {
            out += pattern[i];
        }
    }
    return out;
}

} // namespace

QString Sentence::said(const Arg &arg)
{
    if (const auto *plain = std::get_if<QString>(&arg))
        return *plain;
    if (const auto *local = std::get_if<dev::LocalText>(&arg))
        return localText(*local);
    const auto &sentence = std::get<std::shared_ptr<const Sentence>>(arg);
    return sentence ? sentence->text() : QString();
}

QString Sentence::text() const
{
    if (!m_source)
        return said(m_whole);
    QStringList values;
    for (const Arg &a : m_args)
        values << said(a);
    return fill(QCoreApplication::translate(m_context, m_source), values);
}

QString Sentence::saidInEnglish(const Arg &arg)
{
    if (const auto *plain = std::get_if<QString>(&arg))
        return *plain;
    if (const auto *local = std::get_if<dev::LocalText>(&arg))
        return QString::fromStdString(local->en);
    const auto &sentence = std::get<std::shared_ptr<const Sentence>>(arg);
    return sentence ? sentence->english() : QString();
}

QString Sentence::english() const
{
    if (!m_source)
        return saidInEnglish(m_whole);
    QStringList values;
    for (const Arg &a : m_args)
        values << saidInEnglish(a);
    return fill(QString::fromUtf8(m_source), values);
}

} // namespace vt::model
