// LocalText: a user-visible text carried in both product languages. The protocol core is
// Qt-free, so device messages, field texts and dictionary labels travel as {en, de} pairs and
// the UI picks one at the boundary (STYLE.md rule 13: carried in both languages, tested for
// completeness).
#pragma once

#include <string>

namespace vt::dev {

enum class Language { English, German };

struct LocalText
{
    std::string en;
    std::string de;

    const std::string &in(Language lang) const
    {
        return lang == Language::German && !de.empty() ? de : en;
    }
    bool complete() const { return !en.empty() && !de.empty(); }
    bool operator==(const LocalText &) const = default;
};

// Same words in both languages (names, numbers, hex dumps).
inline LocalText same(std::string text)
{
    return LocalText{text, text};
}

} // namespace vt::dev
