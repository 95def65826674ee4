// What a chapter says on stderr besides its errors: warnings, each one printable line, each said
// once, and at most kMaxWarnings of them in a run whatever the input holds (a model of 5,000
// materials naming 15,000 missing textures prints 16 lines and one that says how many more).
// Every loader and pass warns through here; errors are printed by common/app/cli.cpp with oneLine.
#pragma once

#include <cstdint>
#include <string>

namespace common {

inline constexpr uint32_t kMaxWarnings = 16;

// `message` as one printable line, whatever the input put into it: ASCII control characters,
// the C1 controls (U+0080..U+009F, NEL among them) and the Unicode line and paragraph separators
// (U+2028, U+2029) each become one '?'; past 1,000 bytes it is cut (on a character boundary) and
// ends in "...".
std::string oneLine(std::string message);

// Whether `text` holds a control character: ASCII's (NUL, line breaks, ...), DEL or C1's
// (U+0080..U+009F, as UTF-8). Paths that models and scene files name are refused with one.
bool hasControlCharacter(const std::string& text);

// Prints "warning: <message>" (made one line) unless the same message was printed before in this
// run; after kMaxWarnings lines, one more says that the rest are not shown and the others are
// only counted. Safe to call from several threads.
void warn(const std::string& message);

}  // namespace common
