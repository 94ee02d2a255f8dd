// Sentence: a text for people kept as its catalogue entry and its values until it is shown, so a
// text made before a language switch is said in the language of the moment (a fold note, a write
// result). The values are plain text (numbers, names, words a link chose), bilingual texts from
// devices/, or sentences of their own (the reason inside a note). A value; any thread, but text()
// reads the catalogue in force, so call it where the text is shown.
//
// The entry must reach lupdate: write the source through QT_TR_NOOP inside the class whose tr()
// context it belongs to (or QT_TRANSLATE_NOOP with the context named), e.g.
//     Sentence(staticMetaObject.className(), QT_TR_NOOP("Module %1: %2.")).arg(n).arg(why)
#pragma once

#include "core/local_text.h"

#include <QString>
#include <memory>
#include <variant>
#include <vector>

namespace vt::model {

class Sentence
{
public:
    Sentence() = default;
    // `context` and `source` as tr() has them; both must live as long as the program (literals).
    Sentence(const char *context, const char *source);
    // Words that are already final (an operating system's error, a link's words).
    static Sentence verbatim(QString text);
    // A text from devices/ in both languages (a device's refusal, a dictionary's range error).
    static Sentence bilingual(dev::LocalText text);

    // Fills the next %n, as QString::arg() does, when the sentence is said.
    Sentence &arg(const QString &value);
    Sentence &arg(long long value);
    Sentence &arg(int value) { return arg(static_cast<long long>(value)); }
    Sentence &arg(std::size_t value) { return arg(static_cast<long long>(value)); }
    Sentence &arg(const dev::LocalText &value);
    Sentence &arg(const Sentence &value);

    // In the catalogue and language in force now.
    QString text() const;
    // In the source language (English), whatever catalogue is in force: for logs kept on disk.
    QString english() const;
    bool isEmpty() const;

private:
    using Arg = std::variant<QString, dev::LocalText, std::shared_ptr<const Sentence>>;
    static QString said(const Arg &arg);
    static QString saidInEnglish(const Arg &arg);

    const char *m_context = nullptr;
    const char *m_source = nullptr;
    Arg m_whole; // without a source: the whole text (verbatim or bilingual)
    std::vector<Arg> m_args;
};

} // namespace vt::model
