#pragma once
// A guard for JSON from files and callers: JSON libraries read deep nesting without trouble,
// but writing it back (a message, a copy, a dump) recurses once per level, and 100,000 levels
// overflow the stack. Every reader checks the text first.
#include <string>
#include <string_view>

namespace aeronc {

// Deeper than any file the project reads or writes (the domain tree nests 6 levels).
constexpr int kMaxJsonNesting = 64;

// The deepest nesting of arrays and objects in `text`, brackets inside strings not counted.
// Stops counting once beyond `limit`.
int jsonNesting(std::string_view text, int limit = kMaxJsonNesting);

// Throws inputError "<what>: JSON nested deeper than 64 levels" when it is.
void checkJsonNesting(std::string_view text, const std::string& what);

}  // namespace aeronc
