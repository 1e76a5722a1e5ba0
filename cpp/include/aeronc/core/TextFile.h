#pragma once
// Whole-file text I/O with the project's rules: clear errors, and writes that never leave a
// partial file (written beside the target, then renamed over it).
#include <string>

namespace aeronc {

// Throws inputError "<what> <path> cannot be read" when the file is missing or unreadable.
std::string readTextFile(const std::string& path, const std::string& what);

// Creates missing parent folders. Throws inputError naming the path when it cannot write.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace aeronc
